// Where and how `pear triangulate -o` writes its results.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "inputs.hpp"
#include "pear/io.hpp"

namespace pear::cli {

/// gdal: a layer through a GDAL vector driver (OutputPlan::driver).
enum class OutputFormat { obj, geojson, node, svg, gdal };

/// What --format names: "obj", "geojson", "node", "svg", or (built with GDAL) a GDAL vector
/// driver that creates files ("GPKG", "ESRI Shapefile", "FlatGeobuf", ...); UsageError otherwise.
struct FormatChoice {
  OutputFormat format;
  std::string driver;  ///< for gdal
};
FormatChoice parse_output_format(std::string_view name);

struct OutputPlan {
  std::optional<OutputFormat> format;  ///< none: write nothing
  std::string driver;                  ///< the GDAL driver, for OutputFormat::gdal
  std::string path;                    ///< a file, a directory, or "-" for stdout
  bool directory = false;              ///< one output per input, named after it
};

/// Checks -o and --format against the inputs (UsageError when they do not fit, when two inputs
/// would write the same file, or when an output would overwrite an input).
OutputPlan plan_output(const std::optional<std::string>& output, std::optional<FormatChoice> format,
                       std::span<const Input> inputs);

/// Writes one input's results as the plan says; returns notes for stderr (a GDAL output's
/// renamed fields). Throws std::runtime_error if it cannot.
/// `srid` (0: none) is the input's spatial reference, which the GeoJSON output names; `source`
/// the GDAL layer it came from (fields, FIDs, reference system for a GDAL output), or null;
/// `layer_name` names the output layer (empty: the input file's stem).
std::vector<std::string> write_output(const OutputPlan& plan, const std::string& input,
                                      std::span<const io::TriangulatedPolygon> results,
                                      std::uint32_t srid, const gis::Source* source,
                                      const std::string& layer_name);

}  // namespace pear::cli
