#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "pear/io.hpp"
#include "readers.hpp"

namespace pear::io {

namespace {
bool ends_with_ignoring_case(std::string_view name, std::string_view suffix) {
  if (name.size() < suffix.size()) return false;
  const std::string_view tail = name.substr(name.size() - suffix.size());
  for (std::size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(tail[i])) != suffix[i]) return false;
  return true;
}

/// Whether the text's first word could be hex WKB: 18 or more hex digits, a byte order first.
bool starts_hex_wkb(std::string_view text) {
  const std::size_t end = std::min(text.find_first_of(" \t\r\n"), text.size());
  constexpr std::size_t shortest = 18;  // byte order, type and a count: 9 bytes
  if (end < shortest || end % 2 != 0 || text[0] != '0' || (text[1] != '0' && text[1] != '1'))
    return false;
  for (std::size_t i = 0; i < end; ++i)
    if (!std::isxdigit(static_cast<unsigned char>(text[i]))) return false;
  return true;
}
}  // namespace

Format guess_format(std::string_view name, std::string_view text) {
  for (const std::string_view ext : {".json", ".geojson"})
    if (ends_with_ignoring_case(name, ext)) return Format::geojson;
  if (ends_with_ignoring_case(name, ".wkt")) return Format::wkt;
  if (ends_with_ignoring_case(name, ".poly")) return Format::poly;
  if (ends_with_ignoring_case(name, ".wkb")) return Format::wkb;
  for (const std::string_view ext : {".hexwkb", ".wkb.hex"})
    if (ends_with_ignoring_case(name, ext)) return Format::hex_wkb;
  // A WKB value starts with its byte order, 0 or 1: no text format starts with such a byte.
  if (!text.empty() && (text[0] == '\0' || text[0] == '\1')) return Format::wkb;
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a UTF-8 byte order mark
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return Format::geojson;
  if (starts_hex_wkb(text.substr(first))) return Format::hex_wkb;
  const unsigned char c = static_cast<unsigned char>(text[first]);
  if (std::isalpha(c)) return Format::wkt;
  if (std::isdigit(c) || c == '#' || c == '+') return Format::poly;
  return Format::geojson;  // its reader explains best what a text should have started with
}

std::vector<Polygon> read_text(std::string_view text, Format format, std::string_view name,
                               const ReadOptions& options) {
  switch (format) {
    case Format::wkt:
      return read_wkt(text, name, options);
    case Format::poly:
      return read_poly(text, name, options);
    case Format::wkb:
      return read_wkb(std::as_bytes(std::span(text)), name, options);
    case Format::hex_wkb:
      return read_hex_wkb(text, name, options);
    case Format::geojson:
      break;
  }
  return read_geojson(text, name, options);
}

std::vector<Polygon> detail::polygons_of(ReadResult&& result) {
  std::vector<Polygon> polygons;
  polygons.reserve(result.features.size());
  for (Feature& feature : result.features) polygons.push_back(std::move(feature.polygon));
  return polygons;
}

namespace {
ReadResult read_any(std::string_view text, Format format, std::string_view name,
                    const ReadOptions& options) {
  using detail::Mode;
  switch (format) {
    case Format::wkt:
      return detail::read_wkt(text, name, options, Mode::features);
    case Format::wkb:
      return detail::read_wkb(std::as_bytes(std::span(text)), name, options, Mode::features);
    case Format::hex_wkb:
      return detail::read_hex_wkb(text, name, options, Mode::features);
    case Format::poly: {
      ReadResult result;
      for (Polygon& polygon : read_poly(text, name, options))
        result.features.push_back({std::move(polygon), {}, {}, {}, 0});
      return result;
    }
    case Format::geojson:
      break;
  }
  return detail::read_geojson(text, name, options, Mode::features);
}
}  // namespace

ReadResult read_features(std::string_view text, Format format, std::string_view name,
                         const ReadOptions& options) {
  ReadResult result = read_any(text, format, name, options);
  if (result.features.empty() && !result.skipped.empty()) {
    // Nothing but geometries that are not polygons: the strict reader's error names the first.
    read_text(text, format, name, options);
    const SkippedGeometry& first = result.skipped.front();
    std::string detail = "expected a Polygon or MultiPolygon but found only " +
                         std::to_string(result.skipped.size()) +
                         " geometries that are not, the first a " + first.type;
    if (first.line == 0) detail = "byte " + std::to_string(first.offset) + ": " + detail;
    throw ParseError(std::string(name), first.line, first.column, first.offset, detail);
  }
  return result;
}

namespace {
std::string read_whole(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw ParseError(name, 0, 0, 0, "expected a file but found a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(name, 0, 0, 0, std::string("cannot open: ") + std::strerror(errno));
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0)
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  if (in.bad())
    throw ParseError(name, 0, 0, 0, std::string("cannot read: ") + std::strerror(errno));
  return text;
}
}  // namespace

std::vector<Polygon> read_file(const std::filesystem::path& path, const ReadOptions& options) {
  const std::string text = read_whole(path);
  const std::string name = path.string();
  return read_text(text, guess_format(name, text), name, options);
}

ReadResult read_features_file(const std::filesystem::path& path, const ReadOptions& options) {
  const std::string text = read_whole(path);
  const std::string name = path.string();
  return read_features(text, guess_format(name, text), name, options);
}

}  // namespace pear::io
