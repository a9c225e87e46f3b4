// Well-known text: POLYGON, MULTIPOLYGON and GEOMETRYCOLLECTION (OGC Simple Features), one or
// more per text, each with an optional EWKT SRID prefix. read_features skips points and lines.
#include <cctype>
#include <string>
#include <vector>

#include "pear/io.hpp"
#include "readers.hpp"
#include "scanner.hpp"

namespace pear::io {
namespace {

using detail::Mode;
using detail::NumberSyntax;
using detail::Scanner;

std::string upper(std::string_view word) {
  std::string out(word);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

class WktReader {
 public:
  WktReader(std::string_view text, std::string_view name, const ReadOptions& options, Mode mode)
      : s_(text, name), options_(options), mode_(mode) {}

  ReadResult read() {
    s_.skip_space();
    if (s_.at_end()) s_.fail_expected(s_.pos, "POLYGON or MULTIPOLYGON");
    for (; !s_.at_end(); ++feature_index_) {
      srid_prefix();
      geometry();
      s_.skip_space();
    }
    return std::move(result_);
  }

 private:
  void geometry() {
    const std::size_t at = s_.pos;
    const std::string kind = upper(word());
    const bool other = kind == "POINT" || kind == "LINESTRING" || kind == "MULTIPOINT" ||
                       kind == "MULTILINESTRING";
    if (mode_ == Mode::features && other) return skip(kind, at);
    if (kind != "POLYGON" && kind != "MULTIPOLYGON" && kind != "GEOMETRYCOLLECTION")
      s_.fail_expected(at, "POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION");
    s_.skip_space();
    dimension();
    if (kind == "POLYGON") {
      polygon_text();
    } else if (empty()) {
      return;
    } else if (kind == "MULTIPOLYGON") {
      list([&] { polygon_text(); });
    } else {
      list([&] { geometry(); });
    }
  }

  // A geometry that is no polygon: named in the result, its text passed over.
  void skip(const std::string& kind, std::size_t at) {
    const detail::Location where = s_.location(at);
    result_.skipped.push_back({feature_index_, kind, where.line, where.column, at});
    s_.skip_space();
    dimension();
    if (empty()) return;
    s_.expect('(', "'(' or EMPTY");
    for (int depth = 1; depth > 0; ++s_.pos) {
      if (s_.at_end()) s_.fail_expected(s_.pos, "')'");
      depth += s_.peek() == '(' ? 1 : s_.peek() == ')' ? -1 : 0;
    }
  }

  // PostGIS' EWKT: an optional "SRID=4326;" before the geometry, kept in the result (pear
  // triangulates in the plane of the coordinates, whatever their reference system).
  void srid_prefix() {
    const std::size_t at = s_.pos;
    if (upper(word()) != "SRID") {
      s_.pos = at;
      return;
    }
    s_.expect('=', "'=' after SRID");
    const std::size_t srid_at = s_.pos;
    const std::size_t srid = s_.count("SRID");
    if (srid > 0xFFFFFFFFu) s_.fail_expected(srid_at, "an SRID below 2^32");
    detail::merge_srid(result_, static_cast<std::uint32_t>(srid),
                       [&](const std::string& message) { s_.fail(srid_at, message); });
    s_.expect(';', "';' after the SRID");
    s_.skip_space();
  }

  // Optional Z, M or ZM: how many ordinates each point then has, and which.
  void dimension() {
    const std::size_t at = s_.pos;
    const std::string tag = upper(word());
    if (tag.empty() || tag == "EMPTY") {
      s_.pos = at;
      ordinates_ = 0;  // not given: 2, 3 (z) or 4 (z, m) accepted
      m_only_ = false;
      return;
    }
    if (tag != "Z" && tag != "M" && tag != "ZM") s_.fail_expected(at, "'(', EMPTY, Z, M or ZM");
    ordinates_ = tag == "ZM" ? 4 : 3;
    m_only_ = tag == "M";
    s_.skip_space();
  }

  bool empty() {
    const std::size_t at = s_.pos;
    if (upper(word()) == "EMPTY") return true;
    s_.pos = at;
    return false;
  }

  void polygon_text() {
    if (empty()) return;
    Feature feature;
    feature.feature_index = feature_index_;
    int numbers = 0;  // ordinates per point of this polygon (features mode)
    list([&] {
      const std::size_t ring_at = s_.pos;
      Ring& ring = feature.polygon.emplace_back();
      list([&] {
        const std::size_t at = s_.pos;
        double extra[2];
        int read = 0;
        ring.push_back(point(extra, read));
        if (mode_ == Mode::features) keep_ordinates(feature, at, numbers, extra, read);
      });
      const std::size_t kept = ring.size();
      detail::finish_ring(ring, s_, ring_at, options_);
      if (ring.size() < kept) {  // the closing point
        if (!feature.z.empty()) feature.z.pop_back();
        if (!feature.m.empty()) feature.m.pop_back();
      }
    });
    result_.features.push_back(std::move(feature));
  }

  // z and m of one point: 3 ordinates are x y z (x y m after M), 4 are x y z m.
  void keep_ordinates(Feature& feature, std::size_t at, int& numbers, const double* extra,
                      int read) {
    if (numbers == 0) numbers = read;
    if (read != numbers)
      s_.fail(at, "expected " + std::to_string(numbers) +
                      " ordinates in every point of this polygon, as in its first, but found " +
                      std::to_string(read) + " (its z or m would be partial)");
    if (read == 3) (m_only_ ? feature.m : feature.z).push_back(extra[0]);
    if (read == 4) feature.z.push_back(extra[0]), feature.m.push_back(extra[1]);
  }

  // '(' element (',' element)* ')'
  template <class Element>
  void list(Element element) {
    s_.expect('(', "'('");
    for (;;) {
      s_.skip_space();
      element();
      s_.skip_space();
      if (s_.peek() == ')') break;
      s_.expect(',', "',' or ')'");
    }
    ++s_.pos;
  }

  // x and y; the ordinates after them into `extra`, `read` of them in all.
  Point point(double* extra, int& read) {
    Point p;
    p.x = s_.number(NumberSyntax::loose);
    separator();
    p.y = s_.number(NumberSyntax::loose);
    read = 2;
    for (;;) {
      const std::size_t at = s_.pos;
      s_.skip_space();
      const char c = s_.peek();
      if (c == ',' || c == ')') {
        if (ordinates_ != 0 && read != ordinates_)
          s_.fail_expected(at, std::to_string(ordinates_) + " ordinates per point");
        return p;
      }
      if (at == s_.pos) s_.fail_expected(at, "white space, ',' or ')'");
      if (read == (ordinates_ == 0 ? 4 : ordinates_)) s_.fail_expected(s_.pos, "',' or ')'");
      extra[read - 2] = s_.number(NumberSyntax::loose);
      ++read;
    }
  }

  void separator() {
    const std::size_t at = s_.pos;
    s_.skip_space();
    if (at == s_.pos) s_.fail_expected(at, "white space and the y coordinate");
  }

  std::string_view word() {
    const std::size_t start = s_.pos;
    while (std::isalpha(static_cast<unsigned char>(s_.peek()))) ++s_.pos;
    return s_.text().substr(start, s_.pos - start);
  }

  Scanner s_;
  const ReadOptions& options_;
  Mode mode_;
  int ordinates_ = 0;
  bool m_only_ = false;  // `M` given: a third ordinate is m
  std::size_t feature_index_ = 0;
  ReadResult result_;
};

}  // namespace

ReadResult detail::read_wkt(std::string_view text, std::string_view name,
                            const ReadOptions& options, Mode mode) {
  return WktReader(text, name, options, mode).read();
}

std::vector<Polygon> read_wkt(std::string_view text, std::string_view name,
                              const ReadOptions& options) {
  return detail::polygons_of(detail::read_wkt(text, name, options, Mode::polygons));
}

}  // namespace pear::io
