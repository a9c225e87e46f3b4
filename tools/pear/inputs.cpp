#include "inputs.hpp"

#include <glob.h>
#include <unistd.h>
#if PEAR_HAVE_ZLIB
#include <zlib.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <iterator>

namespace pear::cli {

namespace fs = std::filesystem;

namespace {

bool is_polygon_file(const fs::path& path) {
  std::string name = path.filename().string();
  if (name.ends_with(".gz")) name.resize(name.size() - 3);
  for (const char* ext : {".json", ".geojson", ".wkt", ".poly"})
    if (name.ends_with(ext)) return true;
  return false;
}

/// Walks `top` directory by directory (not following links to directories), so that one that
/// cannot be read is named and the others are still walked.
void add_directory(const fs::path& top, std::vector<Input>& out) {
  std::vector<Input> found;
  std::vector<fs::path> pending{top};
  while (!pending.empty()) {
    const fs::path dir = std::move(pending.back());
    pending.pop_back();
    std::error_code error;
    for (fs::directory_iterator it(dir, error); !error && it != fs::directory_iterator();
         it.increment(error)) {
      std::error_code ignored;  // an entry that vanished or cannot be examined is no input
      if (it->is_symlink(ignored) ? false : it->is_directory(ignored))
        pending.push_back(it->path());
      else if (it->is_regular_file(ignored) && is_polygon_file(it->path()))
        found.push_back({it->path().string(), {}});
    }
    if (error) found.push_back({dir.string(), "cannot read the directory: " + error.message()});
  }
  if (found.empty())
    found.push_back({top.string(), "no .json, .geojson, .wkt or .poly files (or .gz) in it"});
  std::sort(found.begin(), found.end(),
            [](const Input& a, const Input& b) { return a.name < b.name; });
  out.insert(out.end(), found.begin(), found.end());
}

void add(const std::string& name, std::vector<Input>& out) {
  std::error_code error;
  if (fs::is_directory(name, error)) {
    add_directory(name, out);
  } else {
    out.push_back({name, {}});
  }
}

std::string read_gzip(const std::string& name) {
#if PEAR_HAVE_ZLIB
  std::error_code size_error;
  const std::uintmax_t packed = fs::file_size(name, size_error);
  const std::size_t limit =
      size_error ? gzip_inflate_floor
                 : std::max<std::size_t>(gzip_inflate_floor, gzip_max_ratio * packed);
  gzFile file = gzopen(name.c_str(), "rb");
  if (file == nullptr)
    throw io::ParseError(name, 0, 0, 0, std::string("cannot open: ") + std::strerror(errno));
  std::string text;
  char chunk[1 << 16];
  int n = 0;
  while ((n = gzread(file, chunk, sizeof chunk)) > 0) {
    text.append(chunk, static_cast<std::size_t>(n));
    if (text.size() > limit) {
      gzclose(file);
      throw io::ParseError(name, 0, 0, 0,
                           "inflates past " + std::to_string(limit) + " bytes, over " +
                               std::to_string(gzip_max_ratio) + " times its " +
                               std::to_string(packed) +
                               ": refused as a likely decompression bomb (gunzip it to read it)");
    }
  }
  int code = 0;
  const std::string error = n < 0 ? gzerror(file, &code) : "";
  gzclose(file);
  if (n < 0) throw io::ParseError(name, 0, 0, text.size(), "cannot decompress: " + error);
  return text;
#else
  throw io::ParseError(name, 0, 0, 0, "this pear was built without zlib and cannot read .gz");
#endif
}

}  // namespace

std::vector<Input> expand_inputs(std::span<const std::string_view> args) {
  std::vector<Input> out;
  for (const std::string_view arg_view : args) {
    const std::string arg(arg_view);
    std::error_code error;
    if (arg == "-" || fs::exists(arg, error) || arg.find_first_of("*?[") == std::string::npos) {
      add(arg, out);
      continue;
    }
    glob_t matches{};
    if (::glob(arg.c_str(), 0, nullptr, &matches) == 0) {
      for (std::size_t i = 0; i < matches.gl_pathc; ++i) add(matches.gl_pathv[i], out);
    } else {
      out.push_back({arg, {}});  // nothing matched: reading it says so
    }
    globfree(&matches);
  }
  return out;
}

std::vector<Polygon> read_input(const Input& input, const io::ReadOptions& options) {
  const std::string& name = input.name;
  if (!input.problem.empty()) throw io::ParseError(name, 0, 0, 0, input.problem);
  if (name == "-") {
    std::string text(std::istreambuf_iterator<char>(std::cin), {});
    return io::read_text(text, io::guess_format("", text), "<stdin>", options);
  }
  if (!name.ends_with(".gz")) return io::read_file(name, options);
  const std::string text = read_gzip(name);
  const std::string inner = name.substr(0, name.size() - 3);
  return io::read_text(text, io::guess_format(inner, text), name, options);
}

Progress::Progress(std::size_t files)
    : files_(files),
      bar_(files >= 20 && isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

void Progress::advance() {
  ++done_;
  const auto now = std::chrono::steady_clock::now();
  if (bar_ && (now - last_draw_ > std::chrono::milliseconds(100) || done_ == files_)) {
    last_draw_ = now;
    draw();
  }
}

void Progress::draw() {
  constexpr std::size_t width = 40;
  const std::size_t filled = files_ == 0 ? width : done_ * width / files_;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "\r[%s%s] %zu/%zu files  %.1f s", std::string(filled, '#').c_str(),
               std::string(width - filled, '.').c_str(), done_, files_, seconds);
  std::fflush(stderr);
}

void Progress::message(const std::string& text) {
  if (bar_) std::fputs("\r\033[K", stderr);  // clear the bar's line
  std::fprintf(stderr, "%s\n", text.c_str());
  if (bar_ && done_ > 0) draw();
}

void Progress::summary(std::size_t polygons, std::size_t failures) {
  if (bar_) std::fputs("\r\033[K", stderr);
  if (files_ <= 1) return;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "pear: %zu files, %zu polygons, %zu failures, %.2f s\n", files_, polygons,
               failures, seconds);
}

}  // namespace pear::cli
