// Triangle meshes written by pear or by other tools: OBJ and Triangle's .node/.ele pair.
#include <string>

#include "pear/io.hpp"
#include "scanner.hpp"

namespace pear::io {
namespace {

using detail::NumberSyntax;
using detail::Scanner;

bool at_line_end(const Scanner& s) {
  const char c = s.peek();
  return s.at_end() || c == '\n' || c == '\r' || c == '#';
}

void skip_blanks(Scanner& s) {
  while (s.peek() == ' ' || s.peek() == '\t') ++s.pos;
}

void skip_line(Scanner& s) {
  while (!s.at_end() && s.peek() != '\n') ++s.pos;
  if (!s.at_end()) ++s.pos;
}

// One face corner: "a", "a/b", "a//c" or "a/b/c"; returns the 0-based vertex index.
std::uint32_t obj_corner(Scanner& s, std::size_t vertex_count) {
  const std::size_t at = s.pos;
  const long long raw = s.integer("vertex index");
  const long long index = raw < 0 ? static_cast<long long>(vertex_count) + raw : raw - 1;
  if (raw == 0 || index < 0 || index >= static_cast<long long>(vertex_count))
    s.fail(at, "expected a vertex index from 1 to " + std::to_string(vertex_count) +
                   " (or negative) but found " + std::to_string(raw));
  while (s.peek() == '/' || (s.peek() >= '0' && s.peek() <= '9') || s.peek() == '-') ++s.pos;
  return static_cast<std::uint32_t>(index);
}

std::size_t node_count(Scanner& s, const char* what) {
  const std::size_t value = s.count(what);
  s.end_token();
  return value;
}

}  // namespace

Mesh read_obj(std::string_view text, std::string_view name) {
  Scanner s(text, name);
  Mesh mesh;
  while (!s.at_end()) {
    skip_blanks(s);
    const std::string_view rest = text.substr(s.pos);
    if (rest.starts_with("v ") || rest.starts_with("v\t")) {
      ++s.pos;
      skip_blanks(s);
      Point p;
      p.x = s.number(NumberSyntax::loose);
      skip_blanks(s);
      p.y = s.number(NumberSyntax::loose);
      mesh.points.push_back(p);
    } else if (rest.starts_with("f ") || rest.starts_with("f\t")) {
      ++s.pos;
      std::array<std::uint32_t, 3> triangle{};
      for (auto& corner : triangle) {
        skip_blanks(s);
        corner = obj_corner(s, mesh.points.size());
      }
      skip_blanks(s);
      if (!at_line_end(s)) s.fail_expected(s.pos, "the end of a triangle's face line");
      mesh.triangles.push_back(triangle);
    }
    skip_line(s);
  }
  return mesh;
}

Mesh read_node_ele(std::string_view node_text, std::string_view ele_text, std::string_view name) {
  Mesh mesh;
  Scanner node(node_text, std::string(name) + " (.node)");
  node.skip_space_and_comments();
  const std::size_t n = node_count(node, "vertex count");
  const std::size_t dim_at = node.pos;
  if (node_count(node, "dimension") != 2) node.fail_expected(dim_at, "dimension 2");
  const std::size_t extra = node_count(node, "attribute count") + node_count(node, "marker count");
  long long base = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t at = node.pos;
    const long long number = node.integer("vertex number");
    if (i == 0) base = number;
    if (number != base + static_cast<long long>(i) || base < 0 || base > 1)
      node.fail_expected(at, "vertex number " + std::to_string(base + static_cast<long long>(i)));
    node.end_token();
    Point p;
    p.x = node.number(NumberSyntax::loose);
    node.end_token();
    p.y = node.number(NumberSyntax::loose);
    node.end_token();
    for (std::size_t k = 0; k < extra; ++k) {
      node.number(NumberSyntax::loose);
      node.end_token();
    }
    mesh.points.push_back(p);
  }
  if (!node.at_end()) node.fail_expected(node.pos, "end of file after the vertices");

  Scanner ele(ele_text, std::string(name) + " (.ele)");
  ele.skip_space_and_comments();
  const std::size_t t = node_count(ele, "triangle count");
  const std::size_t corners_at = ele.pos;
  if (node_count(ele, "nodes per triangle") != 3)
    ele.fail_expected(corners_at, "3 nodes per triangle");
  const std::size_t attributes = node_count(ele, "attribute count");
  for (std::size_t i = 0; i < t; ++i) {
    ele.integer("triangle number");
    ele.end_token();
    std::array<std::uint32_t, 3> triangle{};
    for (auto& corner : triangle) {
      const std::size_t at = ele.pos;
      const long long v = ele.integer("vertex number") - base;
      if (v < 0 || v >= static_cast<long long>(n))
        ele.fail_expected(at, "a vertex number from " + std::to_string(base) + " to " +
                                  std::to_string(base + static_cast<long long>(n) - 1));
      ele.end_token();
      corner = static_cast<std::uint32_t>(v);
    }
    for (std::size_t k = 0; k < attributes; ++k) {
      ele.number(NumberSyntax::loose);
      ele.end_token();
    }
    mesh.triangles.push_back(triangle);
  }
  if (!ele.at_end()) ele.fail_expected(ele.pos, "end of file after the triangles");
  return mesh;
}

}  // namespace pear::io
