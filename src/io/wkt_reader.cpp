// Well-known text: POLYGON and MULTIPOLYGON (OGC Simple Features), one or more per text, each
// with an optional EWKT SRID prefix.
#include <cctype>
#include <string>
#include <vector>

#include "pear/io.hpp"
#include "scanner.hpp"

namespace pear::io {
namespace {

using detail::NumberSyntax;
using detail::Scanner;

std::string upper(std::string_view word) {
  std::string out(word);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

class WktReader {
 public:
  WktReader(std::string_view text, std::string_view name, const ReadOptions& options)
      : s_(text, name), options_(options) {}

  std::vector<Polygon> read() {
    s_.skip_space();
    if (s_.at_end()) s_.fail_expected(s_.pos, "POLYGON or MULTIPOLYGON");
    while (!s_.at_end()) {
      geometry();
      s_.skip_space();
    }
    return std::move(polygons_);
  }

 private:
  void geometry() {
    srid_prefix();
    const std::size_t at = s_.pos;
    const std::string kind = upper(word());
    if (kind != "POLYGON" && kind != "MULTIPOLYGON")
      s_.fail_expected(at, "POLYGON or MULTIPOLYGON");
    s_.skip_space();
    dimension();
    if (kind == "POLYGON") {
      polygon_text();
    } else if (!empty()) {
      list([&] { polygon_text(); });
    }
  }

  // PostGIS' EWKT: an optional "SRID=4326;" before the geometry. Read and ignored: pear
  // triangulates in the plane of the coordinates, whatever their reference system.
  void srid_prefix() {
    const std::size_t at = s_.pos;
    if (upper(word()) != "SRID") {
      s_.pos = at;
      return;
    }
    s_.expect('=', "'=' after SRID");
    s_.count("SRID");
    s_.expect(';', "';' after the SRID");
    s_.skip_space();
  }

  // Optional Z, M or ZM: how many ordinates each point then has.
  void dimension() {
    const std::size_t at = s_.pos;
    const std::string tag = upper(word());
    if (tag.empty() || tag == "EMPTY") {
      s_.pos = at;
      ordinates_ = 0;  // not given: 2, 3 or 4 accepted
      return;
    }
    if (tag != "Z" && tag != "M" && tag != "ZM") s_.fail_expected(at, "'(', EMPTY, Z, M or ZM");
    ordinates_ = tag == "ZM" ? 4 : 3;
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
    Polygon polygon;
    list([&] {
      const std::size_t ring_at = s_.pos;
      Ring& ring = polygon.emplace_back();
      list([&] { ring.push_back(point()); });
      detail::finish_ring(ring, s_, ring_at, options_);
    });
    polygons_.push_back(std::move(polygon));
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

  Point point() {
    Point p;
    p.x = s_.number(NumberSyntax::loose);
    separator();
    p.y = s_.number(NumberSyntax::loose);
    int read = 2;
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
      s_.number(NumberSyntax::loose);  // z or m: read and ignored
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
  int ordinates_ = 0;
  std::vector<Polygon> polygons_;
};

}  // namespace

std::vector<Polygon> read_wkt(std::string_view text, std::string_view name,
                              const ReadOptions& options) {
  return WktReader(text, name, options).read();
}

}  // namespace pear::io
