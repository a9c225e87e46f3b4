// Input files for the subcommands: expanding directories and globs, reading plain, gzipped and
// standard input, and the progress bar and summary for long runs.
#pragma once

#include <chrono>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gis.hpp"
#include "pear/io.hpp"

namespace pear::cli {

/// One input: a file to read, or a problem found while listing the inputs (a directory that
/// cannot be read, one with no polygon files), reported in order with the files.
struct Input {
  std::string name;
  std::string problem;  ///< empty when `name` is to be read
};

/// The inputs the arguments name: "-" (stdin) and existing files as given, directories walked
/// recursively for .json/.geojson/.wkt/.poly/.wkb/.hexwkb/.wkb.hex (optionally .gz) files, and
/// .gpkg/.shp/.fgb when built with GDAL, in
/// name order (a directory that cannot be read is an input with its problem, and the walk goes
/// on), other arguments expanded as globs. An argument that names nothing is kept, so reading it
/// reports the problem in order with the other files.
std::vector<Input> expand_inputs(std::span<const std::string_view> args);

/// A .gz may inflate to at most this many bytes unless --gzip-limit says otherwise; past it, it
/// is refused as a likely decompression bomb whatever its compressed size (a plain file of any
/// size is read as it is).
inline constexpr std::size_t default_gzip_limit = std::size_t{1} << 30;

/// Reads and parses one input with io::read_features (gzip by zlib when the name ends in .gz,
/// refused past `gzip_limit` inflated bytes), or through GDAL where gis::reads says so (then
/// `choice` picks the layer and features; for pear's own formats giving one is an error).
/// Throws pear::io::ParseError naming the file on any problem, the input's own included.
gis::Read read_input(const Input& input, const io::ReadOptions& options, std::size_t gzip_limit,
                     const gis::LayerChoice& choice = {});

/// read_input for the formats pear reads itself.
io::ReadResult read_own_format(const Input& input, const io::ReadOptions& options,
                               std::size_t gzip_limit);

/// The warnings for what a read skipped, one a geometry ("FILE:LINE:COL: feature K: skipped a
/// LineString (not a polygon)"), at most `limit` and then one line counting the rest.
/// `layer`: read through GDAL, where a place is a feature number, not a line or byte.
std::vector<std::string> skipped_warnings(const std::string& file, const io::ReadResult& result,
                                          bool layer, std::size_t limit = 10);

/// Progress on stderr, only when it is a terminal and there are many files; then a summary.
class Progress {
 public:
  explicit Progress(std::size_t files);
  void advance();
  /// Prints a message on its own line (clearing the bar first).
  void message(const std::string& text);
  /// "pear: N files, P polygons, F failures, T s" on stderr when there was more than one file.
  void summary(std::size_t polygons, std::size_t failures);

 private:
  void draw();
  std::size_t files_;
  std::size_t done_ = 0;
  bool bar_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace pear::cli
