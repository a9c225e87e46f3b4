// Paper §2.1: the bridged boundary cut along vertical split lines into pieces. A variant of
// Sutherland–Hodgman: the crossings of a cycle with the line are sorted along it exactly and
// paired (interior segments), so each side gets weakly simple cycles, not one polygon with
// overlapping edges. Steiner points stay symbolic: each names the input edge it lies on; its
// rounded coordinates only guide the parts' ear clippers, and every triangle at a Steiner point
// is redone exactly from input vertices afterwards (divide_conquer_repair.hpp).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "core/boundary.hpp"
#include "core/fill_vector.hpp"
#include "core/stage.hpp"

namespace pear::detail {

/// A corner of a piece: an input node of the boundary, or a Steiner point on a split line.
/// Low 32 bits: the node or the Steiner point's index; high 32 bits: 0 for a node, else line + 1.
using PieceCorner = std::uint64_t;

inline bool is_steiner(PieceCorner c) {
  return (c >> 32) != 0;
}
inline std::uint32_t corner_index(PieceCorner c) {
  return static_cast<std::uint32_t>(c);
}
inline std::uint32_t corner_line(PieceCorner c) {
  return static_cast<std::uint32_t>(c >> 32) - 1;
}
inline PieceCorner steiner_corner(std::uint32_t line, std::uint32_t index) {
  return (PieceCorner{line} + 1) << 32 | index;
}

struct SteinerPoint {
  std::uint32_t from, to;  ///< the input edge from -> to (boundary nodes) it lies on
  Point pos;               ///< x exactly the line's, y rounded: for the parts' clippers only
};

struct SplitLine {
  double after = 0;  ///< the vertex x the line is placed right after (paper: the m_i-th x)
  double x = std::numeric_limits<double>::quiet_NaN();  ///< NaN until placed, or unused
  std::vector<SteinerPoint> steiner;
};

/// Counterclockwise cycles of corners, one after another.
struct Pieces {
  FillVector<PieceCorner> corners;       ///< resize() leaves new corners to be written
  std::vector<std::uint32_t> starts{0};  ///< piece p is corners[starts[p], starts[p + 1])

  std::size_t count() const { return starts.size() - 1; }
  void close_piece() { starts.push_back(static_cast<std::uint32_t>(corners.size())); }
};

inline const Point& corner_pos(const Boundary& b, const std::vector<SplitLine>& lines,
                               PieceCorner c) {
  return is_steiner(c) ? lines[corner_line(c)].steiner[corner_index(c)].pos
                       : b.pos[corner_index(c)];
}

/// The most Steiner points the split lines of a cycle of n nodes may make: every one costs
/// about as much as a vertex again (pieces, their clipping, the repair), and a line across a
/// star meets most of its spikes (a 50,000-vertex star cut into 4,096 parts: 12 million
/// Steiner points, 80 s and 4 GB).
inline std::size_t max_steiner_points(std::size_t nodes) {
  return nodes / 16 + 64;
}

/// The x values the split lines go right after: the ceil(i * n / parts)-th smallest vertex x
/// (i = 1 .. parts - 1) of a deterministic sample of the cycle, without repeats; fewer lines
/// when the x values do not allow parts - 1 distinct ones. Where those lines would make more
/// than max_steiner_points (estimated from the sample), parts is halved until they do not:
/// the cost stays within a small multiple of clipping the whole boundary. The sample and the
/// count in tasks of ctx (phases "split lines: ..."); the same lines for any threads.
/// `last_share`: the rightmost part's share of vertices against the others' (1: equal parts).
std::vector<double> split_positions(const Boundary& b, const FillVector<PieceCorner>& cycle,
                                    unsigned parts, const RunContext& ctx, double last_share = 1);

/// Splits pieces along one line; keeps its scratch memory between calls.
class PieceSplitter {
 public:
  /// Places lines[line] strictly between lines[line].after and the next larger corner x of
  /// `in`, then cuts every piece of `in` along it into `left` and `right` (appended). Returns
  /// false when the crossings of a piece do not pair up (the input is not weakly simple).
  bool split(const Boundary& b, std::vector<SplitLine>& lines, std::uint32_t line, const Pieces& in,
             Pieces& left, Pieces& right);
  /// split() of `in` as tasks of ctx (the first cut, of the whole cycle, where it would be one
  /// serial task): the line's place and the crossings found in parts, the crossings paired,
  /// the pieces' corners copied in parts. The same pieces and Steiner points as split().
  bool split_in_parts(const Boundary& b, std::vector<SplitLine>& lines, std::uint32_t line,
                      const Pieces& in, Pieces& left, Pieces& right, const RunContext& ctx);

 private:
  struct Crossing {
    std::uint32_t at;       ///< the piece edge corners[at] -> corners[at + 1] crosses
    PieceCorner steiner;    ///< the Steiner point made there
    Point low, high;        ///< the input edge's endpoints, low.x < line x < high.x
    bool rightward;         ///< the edge runs from left to right: the interior is above
    std::uint32_t partner;  ///< the crossing at the other end of its interior segment
  };
  /// A piece's run on one side of the line: the Steiner point of crossing `crossing`, the
  /// corners after it up to crossing `end`'s edge, `end`'s Steiner point; written from `out`.
  struct Run {
    std::uint32_t crossing, end;
    std::size_t out;
  };
  bool place(const Boundary& b, std::vector<SplitLine>& lines, std::uint32_t line, const Pieces& in,
             const RunContext* ctx = nullptr);
  bool crossing_at(const Boundary& b, const std::vector<SplitLine>& lines,
                   const PieceCorner* corners, std::uint32_t count, std::uint32_t i, bool u_left,
                   double x, Crossing& c, SteinerPoint& s) const;
  bool find_crossings(const Boundary& b, std::vector<SplitLine>& lines, std::uint32_t line,
                      const PieceCorner* corners, std::uint32_t count,
                      const RunContext* ctx = nullptr);
  bool pair_crossings(const std::vector<SplitLine>& lines, std::uint32_t line);
  bool emit(const PieceCorner* corners, std::uint32_t count, bool left_side, Pieces& out,
            const RunContext* ctx = nullptr);
  void fill_runs(const PieceCorner* corners, std::uint32_t count, PieceCorner* out,
                 std::size_t from, std::size_t to) const;

  std::vector<Crossing> crossings_;   ///< in cycle order
  std::vector<std::uint32_t> order_;  ///< crossings_ indices bottom to top along the line
  std::vector<std::uint8_t> used_;
  std::vector<Run> runs_;    ///< emit's plan: the runs of one side, in output order
  std::size_t planned_ = 0;  ///< their corners
  std::vector<std::size_t> piece_ends_;
  /// find_crossings in parts: each task's crossings and their Steiner points, in cycle order.
  std::vector<std::vector<std::pair<Crossing, SteinerPoint>>> found_;
};

}  // namespace pear::detail
