#include "output.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

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

/// By the extension: pear's own formats first, then a GDAL driver that claims it.
std::optional<FormatChoice> format_of(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".json") return FormatChoice{OutputFormat::geojson, {}};
  if (ext == ".ele") return FormatChoice{OutputFormat::node, {}};
  for (const FormatName& f : formats)
    if (f.extension == ext) return FormatChoice{f.format, {}};
  if (gis::available())
    if (auto driver = gis::driver_for_extension(ext))
      return FormatChoice{OutputFormat::gdal, *driver};
  return std::nullopt;
}

std::string extension(const OutputPlan& plan) {
  if (*plan.format == OutputFormat::gdal) return gis::extension_of_driver(plan.driver);
  for (const FormatName& f : formats)
    if (f.format == *plan.format) return std::string(f.extension);
  return "";
}

/// The formats --format knows, for messages.
std::string known_formats() {
  return gis::available() ? "obj, geojson, node, svg, or a GDAL vector driver such as GPKG"
                          : "obj, geojson, node, svg";
}

// input.json.gz -> input, input.wkb.hex -> input; "-" -> stdin.
std::string stem(const std::string& input) {
  if (input == "-") return "stdin";
  fs::path path(input);
  if (path.extension() == ".gz") path = path.stem();
  if (path.extension() == ".hex") path = path.stem();
  return path.stem().string();
}

/// The files write_output writes for one input: one, or two for the node format.
std::vector<fs::path> output_files(const OutputPlan& plan, const std::string& input) {
  fs::path path =
      plan.directory ? fs::path(plan.path) / (stem(input) + extension(plan)) : fs::path(plan.path);
  if (*plan.format != OutputFormat::node) return {path};
  path.replace_extension();  // out.node or out.ele -> out.node and out.ele
  return {fs::path(path).concat(".node"), fs::path(path).concat(".ele")};
}

/// A file's device and inode, which every name of it shares; nullopt if it does not exist.
std::optional<std::pair<dev_t, ino_t>> file_id(const fs::path& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return std::nullopt;
  return std::pair{info.st_dev, info.st_ino};
}

/// Refuses an output file that two inputs would write (the second would silently replace the
/// first) and one that is an input (it would be destroyed), naming the inputs.
void check_collisions(const OutputPlan& plan, std::span<const Input> inputs) {
  std::map<std::pair<dev_t, ino_t>, const std::string*> input_of;
  for (const Input& input : inputs) {
    if (input.name == "-" || !input.problem.empty()) continue;
    if (const auto id = file_id(input.name)) input_of.emplace(*id, &input.name);
  }
  std::map<fs::path, const std::string*> writer_of;
  for (const Input& input : inputs) {
    if (!input.problem.empty()) continue;  // it is never read, so never written
    for (const fs::path& file : output_files(plan, input.name)) {
      const auto id = file_id(file);
      if (const auto it = id ? input_of.find(*id) : input_of.end(); it != input_of.end())
        throw UsageError("-o " + plan.path + (file == plan.path ? "" : ": " + file.string()) +
                         " would overwrite the input " + *it->second);
      std::error_code error;  // then the name as it is: the writing will say what is wrong
      const fs::path canonical = fs::weakly_canonical(file, error);
      const auto [it, fresh] = writer_of.emplace(error ? file : canonical, &input.name);
      if (!fresh)
        throw UsageError("-o " + plan.path + ": " + *it->second + " and " + input.name +
                         " would both be written to " + file.string() +
                         " (one output per input, named after it)");
    }
  }
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
           std::span<const io::TriangulatedPolygon> results, std::uint32_t srid) {
  std::size_t triangles = 0;
  for (const auto& r : results) triangles += r.triangles.size();
  switch (format) {
    case OutputFormat::obj:
      io::write_obj(out, results);
      break;
    case OutputFormat::geojson:
      io::write_geojson(out, results, srid);
      break;
    case OutputFormat::svg:
      io::write_svg(out, results,
                    {.title = fs::path(input).filename().string() + ": " +
                              std::to_string(triangles) + " triangles"});
      break;
    case OutputFormat::node:
      throw std::runtime_error("the node format needs two files, not stdout");
    case OutputFormat::gdal:
      throw std::runtime_error("a GDAL format is written to a file, not stdout");
  }
}

}  // namespace

FormatChoice parse_output_format(std::string_view name) {
  for (const FormatName& f : formats)
    if (f.name == name) return {f.format, {}};
  if (gis::available() && gis::is_writable_driver(std::string(name)))
    return {OutputFormat::gdal, std::string(name)};
  throw UsageError("unknown --format '" + std::string(name) + "' (known: " + known_formats() + ")");
}

OutputPlan plan_output(const std::optional<std::string>& output, std::optional<FormatChoice> format,
                       std::span<const Input> inputs) {
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
    if (format->format == OutputFormat::node)
      throw UsageError("--format node writes two files; give -o FILE");
    if (format->format == OutputFormat::gdal)
      throw UsageError("--format " + format->driver + " writes a file; give -o FILE");
  } else if (!plan.directory) {
    if (inputs.size() > 1)
      throw UsageError("-o FILE takes one input; for several, give a directory (ending in '/')");
    if (!format) format = format_of(plan.path);
    if (!format)
      throw UsageError("cannot tell the format of '" + plan.path +
                       "' from its extension; give --format (" + known_formats() + ")");
  } else if (!format) {
    throw UsageError("-o DIRECTORY needs --format (" + known_formats() + ")");
  }
  plan.format = format->format;
  plan.driver = format->driver;
  if (plan.path == "-") return plan;
  check_collisions(plan, inputs);
  if (plan.directory && !fs::create_directories(plan.path, error) && error)
    throw UsageError("cannot create directory " + plan.path + ": " + error.message());
  return plan;
}

std::vector<std::string> write_output(const OutputPlan& plan, const std::string& input,
                                      std::span<const io::TriangulatedPolygon> results,
                                      std::uint32_t srid, const gis::Source* source,
                                      const std::string& layer_name) {
  const OutputFormat format = *plan.format;
  if (plan.path == "-") {
    write(format, std::cout, input, results, srid);
    std::cout.flush();
    return {};
  }
  const std::vector<fs::path> files = output_files(plan, input);
  if (format == OutputFormat::gdal)
    return gis::write(files[0].string(), plan.driver, layer_name.empty() ? stem(input) : layer_name,
                      results, source, srid);
  if (format == OutputFormat::node) {
    std::ofstream node = open(files[0]);
    std::ofstream ele = open(files[1]);
    io::write_node_ele(node, ele, results);
    if (!node.flush()) cannot_write(files[0].string());
    if (!ele.flush()) cannot_write(files[1].string());
    return {};
  }
  std::ofstream out = open(files[0]);
  write(format, out, input, results, srid);
  if (!out.flush()) cannot_write(files[0].string());
  return {};
}

}  // namespace pear::cli
