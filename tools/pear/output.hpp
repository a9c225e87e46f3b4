// Where and how `pear triangulate -o` writes its results.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "inputs.hpp"
#include "pear/io.hpp"

namespace pear::cli {

enum class OutputFormat { obj, geojson, node, svg };

/// "obj", "geojson", "node" or "svg"; UsageError otherwise.
OutputFormat parse_output_format(std::string_view name);

struct OutputPlan {
  std::optional<OutputFormat> format;  ///< none: write nothing
  std::string path;                    ///< a file, a directory, or "-" for stdout
  bool directory = false;              ///< one output per input, named after it
};

/// Checks -o and --format against the inputs (UsageError when they do not fit, when two inputs
/// would write the same file, or when an output would overwrite an input).
OutputPlan plan_output(const std::optional<std::string>& output, std::optional<OutputFormat> format,
                       std::span<const Input> inputs);

/// Writes one input's results as the plan says. Throws std::runtime_error if it cannot.
/// `srid` (0: none) is the input's spatial reference, which the GeoJSON output names.
void write_output(const OutputPlan& plan, const std::string& input,
                  std::span<const io::TriangulatedPolygon> results, std::uint32_t srid);

}  // namespace pear::cli
