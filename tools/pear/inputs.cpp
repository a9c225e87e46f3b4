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
#include <fstream>
#include <iostream>
#include <iterator>

namespace pear::cli {

namespace fs = std::filesystem;

namespace {

bool is_polygon_file(const fs::path& path) {
  std::string name = path.filename().string();
  if (name.ends_with(".gz")) name.resize(name.size() - 3);
  for (const char* ext : {".json", ".geojson", ".wkt", ".poly", ".wkb", ".hexwkb", ".wkb.hex"})
    if (name.ends_with(ext)) return true;
  if (gis::available())
    for (const char* ext : {".gpkg", ".shp", ".fgb"})
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
    found.push_back({top.string(),
                     "no polygon files (.json, .geojson, .wkt, .poly, .wkb, .hexwkb, "
                     ".wkb.hex, or .gz) in it"});
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

#if PEAR_HAVE_ZLIB
/// Inflates a .gz file into memory, member after member as gunzip does. Every failure is a
/// ParseError that names the file and gzip: not gzip data, corrupt, truncated, or inflating past
/// `limit` bytes (refused before more than `limit` is held in memory).
class Gunzip {
 public:
  Gunzip(const std::string& name, std::size_t limit)
      : name_(name), limit_(limit), file_(name, std::ios::binary), in_(1 << 16), out_(1 << 18) {
    if (!file_)
      throw io::ParseError(name, 0, 0, 0, "cannot open: " + std::string(std::strerror(errno)));
    if (inflateInit2(&stream_, 15 + 16) != Z_OK) throw std::bad_alloc();  // +16: gzip only
  }
  Gunzip(const Gunzip&) = delete;
  Gunzip& operator=(const Gunzip&) = delete;
  ~Gunzip() { inflateEnd(&stream_); }

  std::string read() {
    if (!refill() || stream_.avail_in < 2 || in_[0] != 0x1f || in_[1] != 0x8b)
      fail("not gzip data (it does not start with gzip's magic bytes 1f 8b)");
    bool in_member = false;  // a member's header read, its trailer not yet
    bool needs_input = false;
    for (;;) {
      if (stream_.avail_in == 0 && needs_input && !refill()) break;
      if (!in_member && inflateReset(&stream_) != Z_OK) fail("cannot restart zlib");
      in_member = true;
      const int code = inflate_some();
      if (code == Z_STREAM_END) in_member = false;
      // inflate stopped for want of input rather than of room for its output
      needs_input = stream_.avail_out != 0;
      if (code == Z_STREAM_END && stream_.avail_in == 0 && !refill()) break;
    }
    if (in_member) fail("truncated: the file ends inside a compressed stream");
    return std::move(text_);
  }

 private:
  /// Reads the next block of the file; false at its end.
  bool refill() {
    file_.read(reinterpret_cast<char*>(in_.data()), static_cast<std::streamsize>(in_.size()));
    if (file_.bad()) fail("cannot read the file: " + std::string(std::strerror(errno)));
    stream_.next_in = in_.data();
    stream_.avail_in = static_cast<uInt>(file_.gcount());
    offset_ += stream_.avail_in;
    return stream_.avail_in != 0;
  }

  /// One inflate call; its output is appended to the text unless that would pass the limit.
  int inflate_some() {
    stream_.next_out = out_.data();
    stream_.avail_out = static_cast<uInt>(out_.size());
    const int code = inflate(&stream_, Z_NO_FLUSH);
    if (code == Z_MEM_ERROR) throw std::bad_alloc();
    // Z_BUF_ERROR: no progress without more input, which the caller reads.
    if (code != Z_OK && code != Z_STREAM_END && code != Z_BUF_ERROR)
      fail("the data is corrupt near byte " + std::to_string(offset_ - stream_.avail_in) + ": " +
           (stream_.msg ? stream_.msg : "zlib error " + std::to_string(code)));
    const std::size_t produced = out_.size() - stream_.avail_out;
    if (produced > limit_ - text_.size()) refuse();
    text_.append(reinterpret_cast<const char*>(out_.data()), produced);
    return code;
  }

  [[noreturn]] void refuse() const {
    fail("inflates past " + std::to_string(limit_) +
         " bytes (--gzip-limit): refused as a likely decompression bomb (give a larger "
         "--gzip-limit, or gunzip it)");
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw io::ParseError(name_, 0, 0, 0, "gzip: " + what);
  }

  std::string name_;
  std::size_t limit_;
  std::ifstream file_;
  std::vector<unsigned char> in_, out_;
  z_stream stream_{};
  std::uintmax_t offset_ = 0;  // bytes of the file read so far
  std::string text_;
};
#endif

std::string read_gzip(const std::string& name, [[maybe_unused]] std::size_t limit) {
#if PEAR_HAVE_ZLIB
  return Gunzip(name, limit).read();
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

gis::Read read_input(const Input& input, const io::ReadOptions& options, std::size_t gzip_limit,
                     const gis::LayerChoice& choice) {
  const std::string& name = input.name;
  if (!input.problem.empty()) throw io::ParseError(name, 0, 0, 0, input.problem);
  if (gis::reads(name)) return gis::read(name, choice, options);
  if (!gis::available())
    for (const char* ext : {".gpkg", ".shp", ".fgb", ".parquet", ".gml", ".kml", ".sqlite"})
      if (name.ends_with(ext))
        throw io::ParseError(name, 0, 0, 0,
                             std::string("this pear was built without GDAL and cannot read ") +
                                 ext + " files (build with libgdal-dev, Meson option gdal)");
  if (choice.layer || choice.where)
    throw io::ParseError(name, 0, 0, 0,
                         "--layer and --where apply to files read through GDAL, not to this one");
  return {read_own_format(input, options, gzip_limit), nullptr, {}, {}};
}

io::ReadResult read_own_format(const Input& input, const io::ReadOptions& options,
                               std::size_t gzip_limit) {
  const std::string& name = input.name;
  if (name == "-") {
    std::string text(std::istreambuf_iterator<char>(std::cin), {});
    return io::read_features(text, io::guess_format("", text), "<stdin>", options);
  }
  if (!name.ends_with(".gz")) return io::read_features_file(name, options);
  const std::string text = read_gzip(name, gzip_limit);
  const std::string inner = name.substr(0, name.size() - 3);
  return io::read_features(text, io::guess_format(inner, text), name, options);
}

std::vector<std::string> skipped_warnings(const std::string& file, const io::ReadResult& result,
                                          bool layer, std::size_t limit) {
  std::vector<std::string> lines;
  for (const io::SkippedGeometry& g : result.skipped) {
    if (lines.size() == limit) {
      lines.push_back(file + ": skipped " + std::to_string(result.skipped.size() - limit) +
                      " more geometries that are not polygons");
      break;
    }
    const std::string where = layer ? ""
                              : g.line == 0
                                  ? ": byte " + std::to_string(g.offset)
                                  : ":" + std::to_string(g.line) + ":" + std::to_string(g.column);
    lines.push_back(file + where + ": feature " + std::to_string(g.feature_index) + ": skipped a " +
                    g.type + " (not a polygon)");
  }
  return lines;
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
