// pear: reading polygons from GeoJSON, WKT (and PostGIS' EWKT), WKB (and EWKB, binary or hex) and
// Triangle's .poly; writing triangulations as OBJ, GeoJSON, Triangle's .node/.ele and SVG.
//
//   std::vector<pear::Polygon> polygons = pear::io::read_file("lake.geojson");  // throws
//   ParseError for (const auto& polygon : polygons) { auto result = pear::triangulate(polygon); ...
//   }
//
// Readers are strict: a malformed, truncated or binary input, a wrong type, a number that is not a
// finite double (NaN, 1e400) or a ring with fewer than 3 points throws ParseError naming the file,
// line and column (for binary WKB: the byte), what was expected and what was found. A read never
// returns part of a file. Text readers skip a UTF-8 byte order mark at the start.
// Readers drop a ring's closing point when it repeats the first point, so vertex i of a polygon is
// the i-th distinct input point (ring after ring), as pear::triangulate numbers them.
//
// Writers print every coordinate in the shortest decimal form that reads back to the same double
// (std::to_chars), so a written file reads back bit-identical; the SVG picture alone rounds to
// its pixels.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "pear/export.hpp"
#include "pear/geometry.hpp"

namespace pear::io {

/// Thrown by every reader. what() is "FILE:LINE:COL: expected X but found Y"; line and column
/// count from 1, the column in bytes. offset is the byte offset of the problem in the text.
/// Binary WKB has no lines: line and column are 0, what() is "FILE: byte N: ..." and detail()
/// starts with "byte N: ", N being offset.
class PEAR_API ParseError : public std::runtime_error {
 public:
  ParseError(std::string file, std::size_t line, std::size_t column, std::size_t offset,
             std::string detail);
  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  std::size_t column() const { return column_; }
  std::size_t offset() const { return offset_; }
  /// The message without the "FILE:LINE:COL: " prefix.
  const std::string& detail() const { return detail_; }

 private:
  std::string file_;
  std::size_t line_;
  std::size_t column_;
  std::size_t offset_;
  std::string detail_;
};

/// wkb: one binary WKB value; hex_wkb: WKB values as hex text (read_hex_wkb).
enum class Format : std::uint8_t { geojson, wkt, poly, wkb, hex_wkb };

struct ReadOptions {
  /// Accept rings with fewer than 3 points (earcut's fixtures have such "Steiner" holes) and pass
  /// them on; the engine drops such holes with a warning. Off: they are a ParseError.
  bool keep_small_rings = false;
};

/// GeoJSON Polygon, MultiPolygon, Feature, FeatureCollection, GeometryCollection (nested), or a
/// bare array of rings `[[[x,y],...],...]` / array of such polygons. Each Polygon is one entry;
/// an empty Polygon and a Feature with a null geometry give none. Positions may carry a third
/// (altitude) number, which read_features keeps; other geometry types are a ParseError here
/// (read_features skips Point, MultiPoint, LineString and MultiLineString and lists them).
/// `name` is the file name used in error messages.
PEAR_API std::vector<Polygon> read_geojson(std::string_view text,
                                           std::string_view name = "<geojson>",
                                           const ReadOptions& options = {});

/// One or more WKT geometries separated by white space: POLYGON, MULTIPOLYGON,
/// GEOMETRYCOLLECTION of them (with optional Z, M or ZM; extra ordinates ignored here, kept by
/// read_features) or their EMPTY forms. Keywords are case-insensitive. A geometry may carry
/// PostGIS' EWKT prefix `SRID=4326;` (ignored here, kept by read_features).
PEAR_API std::vector<Polygon> read_wkt(std::string_view text, std::string_view name = "<wkt>",
                                       const ReadOptions& options = {});

/// Triangle's .poly: vertices, segments, hole points (and optional regional attributes). The
/// segments must form closed rings (each vertex on exactly two segments). Rings nest even-odd:
/// a ring inside an odd number of others is a hole of the innermost; every other ring starts a
/// polygon. A hole point that lies inside a polygon's filled area contradicts that reading and
/// is a ParseError.
PEAR_API std::vector<Polygon> read_poly(std::string_view text, std::string_view name = "<poly>",
                                        const ReadOptions& options = {});

// WKB (well-known binary): what shapely's `.wkb`, geopandas' to_wkb(), GDAL and PostGIS
// (ST_AsBinary, ST_AsEWKB) write. A value is a Polygon, a MultiPolygon (its parts may differ in
// byte order) or an empty GeometryCollection (GEOS' empty polygon): ISO WKB or PostGIS' EWKB,
// either byte order, with Z, M or ZM ordinates and an EWKB SRID (dropped here, kept by
// read_features). Other types (read_features skips points and lines, also inside a
// GeometryCollection), a value cut short or followed by more bytes, and counts that the bytes
// cannot hold are a ParseError naming the byte, counted from the value's first byte.

/// One WKB value, its bytes exactly (a .wkb file holds one value). Each non-empty Polygon is one
/// entry, rings as the text readers give them (closing point dropped, at least 3 points unless
/// ReadOptions::keep_small_rings); a NaN or infinite coordinate is a ParseError.
PEAR_API std::vector<Polygon> read_wkb(std::span<const std::byte> wkb,
                                       std::string_view name = "<wkb>",
                                       const ReadOptions& options = {});

/// WKB values in hex (upper or lower case), as PostGIS prints geometries and `ST_AsHexEWKB`
/// writes them: one or more values separated by white space, usually one per line. Errors
/// name the line and column of the byte's hex digits, and "value K, byte N" (K from 1).
PEAR_API std::vector<Polygon> read_hex_wkb(std::string_view text,
                                           std::string_view name = "<hex wkb>",
                                           const ReadOptions& options = {});

/// Polygons of many geometries as flat arrays: the layout of pear::PolygonBatch (pass
/// coordinates, ring_offsets and polygon_offsets) and of shapely 2's to_ragged_array, one level
/// more. Point i is (coordinates[2i], coordinates[2i+1]); ring r is points [ring_offsets[r],
/// ring_offsets[r+1]); polygon p is rings [polygon_offsets[p], polygon_offsets[p+1]); geometry
/// g is polygons [geometry_offsets[g], geometry_offsets[g+1]). As constructed: no geometries,
/// each offset array holding its leading 0. With keep_z, read_wkb also gives point i's z in z[i]
/// (NaN for a value without Z), for triangles whose points keep their height.
struct PolygonArrays {
  std::vector<double> coordinates;
  std::vector<std::int64_t> ring_offsets{0};
  std::vector<std::int64_t> polygon_offsets{0};
  std::vector<std::int64_t> geometry_offsets{0};
  bool keep_z = false;
  std::vector<double> z;
};

/// Appends one WKB value to `out` as its next geometry, for many geometries without a Polygon
/// object each (pear.triangulate_many over shapely geometries). Rings are kept as the value
/// has them, closing point included, so point i of the geometry is the i-th coordinate it
/// lists; coordinates are not checked (pear::triangulate_batch reports NaN or a short ring).
/// One polygon per non-empty Polygon or MultiPolygon part; an empty span is a missing
/// geometry, with no polygons. On a ParseError `out` is as it was before the call.
PEAR_API void read_wkb(std::span<const std::byte> wkb, PolygonArrays& out,
                       std::string_view name = "<wkb>");

/// Reads by format; for Format::wkb `text` holds the value's bytes. read_file picks the format
/// from the extension (.json, .geojson, .wkt, .poly, .wkb; .hexwkb or .wkb.hex for hex WKB) or,
/// failing that, from the content: a first byte 0 or 1 is binary WKB (a WKB byte order, which
/// no text starts with), a first word of 18 or more hex digits starting 00 or 01 is hex WKB,
/// else the first non-blank character decides. Throws ParseError, also for a file that cannot
/// be opened (line 0).
PEAR_API std::vector<Polygon> read_text(std::string_view text, Format format, std::string_view name,
                                        const ReadOptions& options = {});
PEAR_API std::vector<Polygon> read_file(const std::filesystem::path& path,
                                        const ReadOptions& options = {});
/// The format read_file would use for this name and content.
PEAR_API Format guess_format(std::string_view name, std::string_view text);

// Reading with what the file says beside the rings: z (and m) per vertex, a GeoJSON Feature's
// properties, which geometry of the file a polygon came from, the SRID, and the geometries
// that are not polygons (skipped and named instead of failing the whole file).

/// One polygon of a file with its side data. A MultiPolygon (or a collection) gives one Feature
/// per polygon part; the parts share feature_index and properties.
struct Feature {
  Polygon polygon = {};
  /// Empty when the input has no z; else one per vertex of `polygon`, ring after ring (so z[i]
  /// belongs to vertex i as pear::triangulate numbers them; the closing point is dropped).
  std::vector<double> z = {};
  /// Likewise for m (WKT `M`/`ZM`, WKB M/ZM); GeoJSON has none.
  std::vector<double> m = {};
  /// GeoJSON: the Feature's "properties" object as its JSON text, verbatim; empty when the
  /// Feature has `null` or none, and for every other format.
  std::string properties = {};
  /// Which geometry of the file: the index of a FeatureCollection's feature, of a top-level
  /// GeometryCollection's geometry, of a WKT geometry or hex WKB value in the text (from 0);
  /// 0 for a file of one geometry (a bare GeoJSON array of polygons and a .poly file count as
  /// one).
  std::size_t feature_index = 0;
};

/// A geometry that is no polygon (GeoJSON Point, MultiPoint, LineString, MultiLineString; the
/// same in WKT and WKB), skipped by read_features.
struct SkippedGeometry {
  std::size_t feature_index = 0;     ///< as Feature::feature_index
  std::string type;                  ///< as the file spells it: "LineString", "POINT", "WKB type 2"
  std::size_t line = 0, column = 0;  ///< where it starts (0 for binary WKB)
  std::size_t offset = 0;            ///< its byte offset (in a WKB value: in that value)
};

struct ReadResult {
  std::vector<Feature> features;
  std::vector<SkippedGeometry> skipped;
  /// The spatial reference's EPSG code: EWKT `SRID=N;`, an EWKB SRID, or a GeoJSON "crs"
  /// member naming EPSG:N (the 2008 GeoJSON form GDAL writes); 0 when the file gives none.
  std::uint32_t srid = 0;
};

/// Reads like read_text/read_file, but keeps z and m, properties and feature indices, and
/// skips geometries that are no polygon (listed in `skipped`) where read_text fails on them.
/// A file whose geometries are all skipped is still a ParseError (at the first of them), and
/// so are: positions of one polygon that differ in having a z (its z would be partial),
/// geometries of one text with different SRIDs, and GeoJSON properties that are neither an
/// object nor null.
PEAR_API ReadResult read_features(std::string_view text, Format format, std::string_view name,
                                  const ReadOptions& options = {});
PEAR_API ReadResult read_features_file(const std::filesystem::path& path,
                                       const ReadOptions& options = {});

/// A triangle mesh: points and counterclockwise index triples into them.
struct Mesh {
  std::vector<Point> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// Reads `v x y [z]` and `f a b c` lines of an OBJ file (1-based or negative indices; only
/// triangles; other statements ignored). For comparing with other tools and for round trips.
PEAR_API Mesh read_obj(std::string_view text, std::string_view name = "<obj>");
/// Reads Triangle's .node and .ele pair (0- or 1-based numbering, as the .node file starts).
PEAR_API Mesh read_node_ele(std::string_view node_text, std::string_view ele_text,
                            std::string_view name = "<node/ele>");

/// One triangulated polygon for the writers: its rings (as read) and triangles indexing its
/// points ring after ring. `part` is empty or has one entry per triangle: the thread or
/// partition that produced it (the SVG colours by it). The rest is what read_features gave
/// (a Feature's z, m, properties and feature_index) and the run's status, for OBJ and GeoJSON.
struct TriangulatedPolygon {
  Polygon polygon = {};
  std::vector<std::array<std::uint32_t, 3>> triangles = {};
  std::vector<std::uint32_t> part = {};
  std::vector<double> z = {};  ///< empty, or one per point (writers throw invalid_argument else)
  /// Empty, or one m per point, as z. The writers below do not write it (OBJ, SVG and GeoJSON
  /// have no place for it: RFC 7946 positions are x, y and an optional z; .node could hold it
  /// as a vertex attribute); the CLI writes it to GDAL layers with M.
  std::vector<double> m = {};
  std::string properties = {};  ///< a JSON object's text, or empty
  std::size_t feature_index = 0;
  Status status = Status::ok;
};

/// OBJ: `v x y z` for every point (z 0 where the polygon has none), `f a b c` (1-based) for
/// every triangle, one `o` per polygon. pear's triangles use only the input's vertices (no
/// option adds a point), so each vertex keeps its input z exactly.
PEAR_API void write_obj(std::ostream& out, std::span<const TriangulatedPolygon> polygons);
/// GeoJSON FeatureCollection: one Feature per polygon, its geometry a MultiPolygon of triangles
/// (positions [x, y, z] where the polygon has z; m is not written: GeoJSON has no place for
/// it). Its properties are the input's (the members
/// of `properties`, verbatim) and pear's own under one key, which replaces an input member of
/// that name: "pear": {"index": the polygon's place in the output (from 0), "feature": its
/// feature_index, "triangles": how many, "status": "ok" or why not (pear::to_string)}. An
/// `srid` other than 0 and 4326 (GeoJSON's default, WGS 84) is written as the 2008 form's
/// "crs" member, {"type":"name","properties":{"name":"urn:ogc:def:crs:EPSG::N"}}, which GDAL
/// reads.
PEAR_API void write_geojson(std::ostream& out, std::span<const TriangulatedPolygon> polygons,
                            std::uint32_t srid = 0);
/// Triangle's .node (all points, numbered from 0) and .ele (triangles) pair.
PEAR_API void write_node_ele(std::ostream& node, std::ostream& ele,
                             std::span<const TriangulatedPolygon> polygons);

struct SvgOptions {
  double size = 1000;      ///< the longer side of the picture, in pixels (1 to 1e6)
  bool draw_edges = true;  ///< draw triangle edges (thin, scaled to the triangle density)
  std::string title = {};  ///< shown in a band under the picture when not empty
};
/// The most points one <path> of write_svg holds (about 40 kB of path data).
inline constexpr std::size_t svg_path_points_max = 4096;
/// A picture of the polygons (holes visible) and their triangles, y up: the polygons' bounding
/// box is scaled to `size` pixels on its longer side, with a margin of 2% of `size` all round.
/// Layers: the polygons filled (even-odd, so holes stay open), the triangles coloured by `part`,
/// the rings outlined, the title. Coordinates are rounded to 1/10 pixel (so the picture holds
/// its detail up to a zoom of about 10) and a triangle that covers no area on that grid is left
/// out. Large inputs stay drawable: each <path> holds at most svg_path_points_max points, so no
/// attribute comes near libxml2's 10 MB limit (rsvg-convert); long rings are outlined in runs,
/// and the fill is cut into tiles along whole pixels (only a one-pixel tile that still holds
/// more, which takes rings folding back and forth inside one pixel, is kept whole). Eurasia's
/// 1.5 million vertices make a file of about 8 MB that rsvg-convert and Chromium draw in a few
/// seconds.
/// Throws std::invalid_argument for a non-finite point, a triangle index past the points or a
/// size out of range.
PEAR_API void write_svg(std::ostream& out, std::span<const TriangulatedPolygon> polygons,
                        const SvgOptions& options = {});

/// Polygons as GeoJSON (one Polygon, or a MultiPolygon for several; rings written closed), as
/// WKT (one POLYGON per line) or as a .poly file: inputs for pear and for other tools.
PEAR_API void write_geojson_polygons(std::ostream& out, std::span<const Polygon> polygons);
PEAR_API void write_wkt(std::ostream& out, std::span<const Polygon> polygons);
/// Writes a hole point inside each hole; throws std::invalid_argument if a hole has no interior
/// point that can be found (a ring with zero area).
PEAR_API void write_poly(std::ostream& out, std::span<const Polygon> polygons);

/// The shortest decimal text that reads back to exactly `value`.
PEAR_API std::string format_double(double value);

}  // namespace pear::io
