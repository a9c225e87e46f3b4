// pear: synthetic polygon families with a closed form (koch, comb, spiral, holes) and the random
// star; the dispatch by name. The shapes and counts follow ../shared/corpus/synthetic/README.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "generate_internal.hpp"
#include "pear/generate.hpp"
#include "pear/predicates.hpp"

namespace pear {
namespace generate_detail {

std::uint64_t family_seed(std::uint64_t seed, std::uint64_t family) {
  // splitmix64's finalizer: nearby seeds give unrelated streams.
  std::uint64_t z = seed + family * 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

bool strictly_around(const Ring& ring, const Point& center) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (orient2d(center, ring[i], ring[(i + 1) % ring.size()]) <= 0) return false;
  }
  return true;
}

Polygon star(std::size_t vertices, std::uint64_t seed) {
  if (vertices < 3) throw std::invalid_argument("star: needs at least 3 vertices");
  // Random angles can coincide or leave a gap of half a turn; then we draw again.
  for (std::uint64_t attempt = 0; attempt < 1000; ++attempt) {
    Rng rng(family_seed(seed, 1 + (attempt << 8)));
    std::vector<double> angles(vertices);
    for (double& angle : angles) angle = 2 * std::numbers::pi * rng.uniform();
    std::sort(angles.begin(), angles.end());
    Ring ring(vertices);
    for (std::size_t i = 0; i < vertices; ++i) {
      const double radius = rng.uniform(0.5, 1.0);
      ring[i] = {radius * std::cos(angles[i]), radius * std::sin(angles[i])};
    }
    if (strictly_around(ring, Point{0, 0})) return {ring};
  }
  throw std::invalid_argument("star: no simple star polygon found for this size and seed");
}

Polygon comb(std::size_t vertices) {
  // Teeth of width 1 and gap 1, 10 high over a base 1 high; 4 vertices per tooth.
  const std::size_t teeth = std::max<std::size_t>(1, (vertices + 2) / 4);
  const double right = static_cast<double>(2 * teeth - 1);
  Ring ring;
  ring.reserve(4 * teeth);
  ring.push_back({0, 0});
  ring.push_back({right, 0});
  for (std::size_t t = teeth; t-- > 0;) {
    const double x = static_cast<double>(2 * t);
    ring.push_back({x + 1, 11});
    ring.push_back({x, 11});
    if (t > 0) {
      ring.push_back({x, 1});
      ring.push_back({x - 1, 1});
    }
  }
  return {ring};
}

Polygon spiral(std::size_t vertices) {
  // Archimedean band r = 1 + t .. 1.5 + t at angle 2*pi*t, t in [0, 20]: 20 turns, spacing 1,
  // width 0.5. Out along the outer side, back along the inner side. Below 16 points per turn
  // and side, chords of one turn could cut into the next.
  constexpr double turns = 20;
  if (vertices < 640) throw std::invalid_argument("spiral: needs at least 640 vertices");
  const std::size_t outer = (vertices + 1) / 2;
  const std::size_t inner = vertices / 2;
  Ring ring;
  ring.reserve(vertices);
  auto add = [&](std::size_t i, std::size_t count, double base) {
    const double t = turns * static_cast<double>(i) / static_cast<double>(count - 1);
    const double radius = base + t;
    const double angle = 2 * std::numbers::pi * t;
    ring.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  };
  for (std::size_t i = 0; i < outer; ++i) add(i, outer, 1.5);
  for (std::size_t i = inner; i-- > 0;) add(i, inner, 1.0);
  return {ring};
}

Polygon koch(std::size_t vertices) {
  // Depth d has 3 * 4^d vertices; the nearest depth up to 11 (12.6 million vertices).
  std::size_t depth = 0;
  for (std::size_t d = 1; d <= 11; ++d) {
    const auto count = [](std::size_t k) { return std::size_t{3} << (2 * k); };
    const auto distance = [&](std::size_t k) {
      return count(k) > vertices ? count(k) - vertices : vertices - count(k);
    };
    if (distance(d) < distance(depth)) depth = d;
  }
  const double sin60 = std::sqrt(3.0) / 2;
  Ring ring = {{0, 0}, {1, 0}, {0.5, sin60}};
  for (std::size_t level = 0; level < depth; ++level) {
    Ring next;
    next.reserve(4 * ring.size());
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point a = ring[i];
      const Point b = ring[(i + 1) % ring.size()];
      const Point third = {(b.x - a.x) / 3, (b.y - a.y) / 3};
      const Point p1 = {a.x + third.x, a.y + third.y};
      // The bump points outward: to the right of a counterclockwise ring's edge (turn by -60°).
      const Point peak = {p1.x + 0.5 * third.x + sin60 * third.y,
                          p1.y - sin60 * third.x + 0.5 * third.y};
      next.insert(next.end(), {a, p1, peak, {a.x + 2 * third.x, a.y + 2 * third.y}});
    }
    ring = std::move(next);
  }
  return {ring};
}

Polygon holes(std::size_t vertices) {
  // The square [0, 3k]^2 with k x k unit square holes at (1 + 3i, 1 + 3j): 4 + 4k^2 vertices.
  if (vertices < 8) throw std::invalid_argument("holes: needs at least 8 vertices");
  const auto k =
      static_cast<std::size_t>(std::llround(std::sqrt(static_cast<double>(vertices - 4) / 4)));
  const double side = 3.0 * static_cast<double>(k);
  Polygon polygon;
  polygon.reserve(1 + k * k);
  polygon.push_back({{0, 0}, {side, 0}, {side, side}, {0, side}});
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) {
      const double x = 1 + 3.0 * static_cast<double>(i);
      const double y = 1 + 3.0 * static_cast<double>(j);
      polygon.push_back({{x, y}, {x, y + 1}, {x + 1, y + 1}, {x + 1, y}});
    }
  }
  return polygon;
}

}  // namespace generate_detail

namespace {
constexpr std::array<std::string_view, 8> kinds = {"star",    "comb",   "spiral", "koch",
                                                   "hilbert", "random", "holes",  "random-holes"};
}  // namespace

std::span<const std::string_view> generator_kinds() {
  return kinds;
}

Polygon generate_polygon(std::string_view kind, std::size_t vertices, std::uint64_t seed) {
  using namespace generate_detail;
  if (kind == "star") return star(vertices, seed);
  if (kind == "comb") return comb(vertices);
  if (kind == "spiral") return spiral(vertices);
  if (kind == "koch") return koch(vertices);
  if (kind == "hilbert") return hilbert(vertices);
  if (kind == "random") return random_maze(vertices, seed);
  if (kind == "holes") return holes(vertices);
  if (kind == "random-holes") return random_holes(vertices, seed);
  std::string message = "generate_polygon: unknown kind '";
  message.append(kind).append("'; known:");
  for (std::string_view known : kinds) message.append(" ").append(known);
  throw std::invalid_argument(message);
}

}  // namespace pear
