"""pear's status codes and exceptions (raised by the C++ module too)."""
import enum


class Status(enum.IntEnum):
    """A polygon's outcome; the values are pear::Status's (triangulate_many's status array)."""
    ok = 0              #: a valid triangulation
    not_simple = 1      #: rings cross or overlap: a best-effort triangulation
    invalid_input = 2   #: nothing triangulated: too few points, NaN, bad offsets, ...
    index_overflow = 3  #: more points than uint32 indices can number


class PearError(Exception):
    """Base of pear's exceptions."""


class InvalidInputError(PearError, ValueError):
    """The polygon cannot be triangulated at all (pear.Status.invalid_input).

    issue: what is wrong ("non_finite_coordinate", "outer_ring_too_small", ...); ring (0 = the
    outer ring) and vertex (within that ring, the caller's numbering): where; diagnostics: every
    pear.Diagnostic of the run.
    """

    def __init__(self, message, issue="invalid_input", ring=0, vertex=0, diagnostics=()):
        super().__init__(message)
        self.issue, self.ring, self.vertex = issue, ring, vertex
        self.diagnostics = list(diagnostics)

    def __reduce__(self):
        return type(self), (str(self), self.issue, self.ring, self.vertex, self.diagnostics)


class NotSimpleError(PearError, ValueError):
    """The polygon is not simple (rings cross or overlap; pear.Status.not_simple).

    triangles: the best-effort triangulation pear still made ((M, 3) uint32); diagnostics: where
    (each a pear.Diagnostic naming ring and vertex). triangulate(..., strict=False) returns
    (triangles, pear.Status.not_simple) instead of raising this.
    """
    status = Status.not_simple

    def __init__(self, message, triangles=None, diagnostics=()):
        super().__init__(message)
        self.triangles = triangles
        self.diagnostics = list(diagnostics)

    def __reduce__(self):
        return type(self), (str(self), self.triangles, self.diagnostics)


class WKBError(PearError, ValueError):
    """A WKB value that cannot be read: index (of the geometry in the input) and offset (byte)."""

    def __init__(self, message, index=0, offset=0):
        super().__init__(message)
        self.index, self.offset = index, offset

    def __reduce__(self):
        return type(self), (str(self), self.index, self.offset)
