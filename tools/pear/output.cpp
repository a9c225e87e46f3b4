#include "output.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "cli.hpp"

namespace pear::cli {

namespace fs = std::filesystem;

namespace {

struct FormatName {
  std::string_view name;
  OutputFormat format;
  std::string_view extension;
};
constexpr FormatName formats[] = {{"obj", OutputFormat::obj, ".obj"},
                                  {"geojson", OutputFormat::geojson, ".geojson"},
                                  {"node", OutputFormat::node, ".node"},
                                  {"svg", OutputFormat::svg, ".svg"}};

std::optional<OutputFormat> format_of(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".json") return OutputFormat::geojson;
  if (ext == ".ele") return OutputFormat::node;
  for (const FormatName& f : formats)
    if (f.extension == ext) return f.format;
  return std::nullopt;
}

std::string_view extension(OutputFormat format) {
  for (const FormatName& f : formats)
    if (f.format == format) return f.extension;
  return "";
}

// input.json.gz -> input; "-" -> stdin.
std::string stem(const std::string& input) {
  if (input == "-") return "stdin";
  fs::path path(input);
  if (path.extension() == ".gz") path = path.stem();
  return path.stem().string();
}

/// "cannot write PATH: REASON", the reason from errno right after the failed call.
[[noreturn]] void cannot_write(const std::string& path) {
  throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
}

std::ofstream open(const fs::path& path) {
  errno = 0;
  std::ofstream out(path, std::ios::binary);
  if (!out) cannot_write(path.string());
  return out;
}

void write(OutputFormat format, std::ostream& out, const std::string& input,
           std::span<const io::TriangulatedPolygon> results) {
  std::size_t triangles = 0;
  for (const auto& r : results) triangles += r.triangles.size();
  switch (format) {
    case OutputFormat::obj:
      io::write_obj(out, results);
      break;
    case OutputFormat::geojson:
      io::write_geojson(out, results);
      break;
    case OutputFormat::svg:
      io::write_svg(out, results,
                    {.title = fs::path(input).filename().string() + ": " +
                              std::to_string(triangles) + " triangles"});
      break;
    case OutputFormat::node:
      throw std::runtime_error("the node format needs two files, not stdout");
  }
}

}  // namespace

OutputFormat parse_output_format(std::string_view name) {
  for (const FormatName& f : formats)
    if (f.name == name) return f.format;
  throw UsageError("unknown --format '" + std::string(name) + "' (known: obj, geojson, node, svg)");
}

OutputPlan plan_output(const std::optional<std::string>& output, std::optional<OutputFormat> format,
                       std::size_t inputs) {
  OutputPlan plan;
  if (!output) {
    if (format) throw UsageError("--format needs -o OUT");
    return plan;
  }
  plan.path = *output;
  std::error_code error;
  plan.directory = plan.path.ends_with('/') || fs::is_directory(plan.path, error);
  if (plan.path == "-") {
    if (!format) throw UsageError("-o - (stdout) needs --format");
    if (*format == OutputFormat::node)
      throw UsageError("--format node writes two files; give -o FILE");
  } else if (!plan.directory) {
    if (inputs > 1)
      throw UsageError("-o FILE takes one input; for several, give a directory (ending in '/')");
    if (!format) format = format_of(plan.path);
    if (!format)
      throw UsageError("cannot tell the format of '" + plan.path +
                       "' from its extension; give --format obj|geojson|node|svg");
  } else {
    if (!format) throw UsageError("-o DIRECTORY needs --format obj|geojson|node|svg");
    fs::create_directories(plan.path, error);
    if (error) throw UsageError("cannot create directory " + plan.path + ": " + error.message());
  }
  plan.format = format;
  return plan;
}

void write_output(const OutputPlan& plan, const std::string& input,
                  std::span<const io::TriangulatedPolygon> results) {
  const OutputFormat format = *plan.format;
  if (plan.path == "-") {
    write(format, std::cout, input, results);
    std::cout.flush();
    return;
  }
  fs::path path = plan.directory
                      ? fs::path(plan.path) / (stem(input) + std::string(extension(format)))
                      : fs::path(plan.path);
  if (format == OutputFormat::node) {
    path.replace_extension();  // out.node or out.ele -> out.node and out.ele
    std::ofstream node = open(fs::path(path).concat(".node"));
    std::ofstream ele = open(fs::path(path).concat(".ele"));
    io::write_node_ele(node, ele, results);
    if (!node.flush() || !ele.flush()) cannot_write(path.string() + ".node/.ele");
    return;
  }
  std::ofstream out = open(path);
  write(format, out, input, results);
  if (!out.flush()) cannot_write(path.string());
}

}  // namespace pear::cli
