// Cost of the exact predicates against the plain floating-point determinant, on easy (random)
// inputs, near-degenerate ones (points rounded onto a line or circle) and exactly degenerate ones
// whose coordinate differences are not representable (the adaptive scheme's worst case).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "pear/predicates.hpp"

namespace {

using pear::Point;

enum class Inputs { random, near_degenerate, degenerate };

constexpr std::size_t input_count = 4096;  // a power of two, cycled through

class Random {
 public:
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }
  double uniform(double low, double high) { return low + (high - low) * unit(); }
  // Random significand and sign, magnitude about 2^[-60, 60].
  double spread() {
    const double m = std::ldexp(1.0 + unit(), static_cast<int>(engine_() % 121) - 60);
    return (engine_() & 1) != 0 ? -m : m;
  }

 private:
  std::mt19937_64 engine_{42};
};

std::vector<std::array<Point, 3>> orient2d_inputs(Inputs kind) {
  Random random;
  std::vector<std::array<Point, 3>> inputs(input_count);
  for (auto& [a, b, c] : inputs) {
    if (kind == Inputs::random) {
      a = {random.unit(), random.unit()};
      b = {random.unit(), random.unit()};
      c = {random.unit(), random.unit()};
    } else if (kind == Inputs::near_degenerate) {  // c rounded onto segment ab
      a = {random.uniform(0.5, 2), random.uniform(0.5, 2)};
      b = {random.uniform(0.5, 2), random.uniform(0.5, 2)};
      const double t = random.unit();
      c = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    } else {  // on y = x with unrelated magnitudes
      const double x = random.spread(), y = random.spread(), z = random.spread();
      a = {x, x};
      b = {y, y};
      c = {z, z};
    }
  }
  return inputs;
}

std::vector<std::array<Point, 4>> incircle_inputs(Inputs kind) {
  Random random;
  std::vector<std::array<Point, 4>> inputs(input_count);
  for (auto& quad : inputs) {
    if (kind == Inputs::random) {
      for (Point& p : quad) p = {random.unit(), random.unit()};
    } else if (kind == Inputs::near_degenerate) {  // rounded points on one circle
      const double cx = random.uniform(1, 1.5), cy = random.uniform(1, 1.5);
      const double radius = random.uniform(0.1, 0.5);
      for (Point& p : quad) {
        const double angle = 2 * std::numbers::pi * random.unit();
        p = {cx + radius * std::cos(angle), cy + radius * std::sin(angle)};
      }
    } else {  // corners of a rectangle with unrelated magnitudes
      const double x0 = random.spread(), x1 = random.spread();
      const double y0 = random.spread(), y1 = random.spread();
      quad = {Point{x0, y0}, Point{x1, y0}, Point{x1, y1}, Point{x0, y1}};
    }
  }
  return inputs;
}

// The baselines: plain determinants, inlined as a caller would write them, and behind a call.
double incircle_inexact(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double adx = a.x - d.x, ady = a.y - d.y;
  const double bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  return (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
         (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
         (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
}

[[gnu::noinline]] double orient2d_inexact_call(const Point& a, const Point& b, const Point& c) {
  return pear::orient2d_inexact(a, b, c);
}

[[gnu::noinline]] double incircle_inexact_call(const Point& a, const Point& b, const Point& c,
                                               const Point& d) {
  return incircle_inexact(a, b, c, d);
}

template <class Predicate>
void bench_orient2d(benchmark::State& state, Predicate predicate, Inputs kind) {
  const auto inputs = orient2d_inputs(kind);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [a, b, c] = inputs[i];
    benchmark::DoNotOptimize(predicate(a, b, c));
    i = (i + 1) & (input_count - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

template <class Predicate>
void bench_incircle(benchmark::State& state, Predicate predicate, Inputs kind) {
  const auto inputs = incircle_inputs(kind);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& [a, b, c, d] = inputs[i];
    benchmark::DoNotOptimize(predicate(a, b, c, d));
    i = (i + 1) & (input_count - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

const auto plain_orient2d = [](const Point& a, const Point& b, const Point& c) {
  return pear::orient2d_inexact(a, b, c);
};
const auto plain_incircle = [](const Point& a, const Point& b, const Point& c, const Point& d) {
  return incircle_inexact(a, b, c, d);
};

BENCHMARK_CAPTURE(bench_orient2d, plain_inline_random, plain_orient2d, Inputs::random);
BENCHMARK_CAPTURE(bench_orient2d, plain_call_random, orient2d_inexact_call, Inputs::random);
BENCHMARK_CAPTURE(bench_orient2d, exact_random, pear::orient2d, Inputs::random);
BENCHMARK_CAPTURE(bench_orient2d, exact_near_collinear, pear::orient2d, Inputs::near_degenerate);
BENCHMARK_CAPTURE(bench_orient2d, exact_collinear_inexact_differences, pear::orient2d,
                  Inputs::degenerate);

BENCHMARK_CAPTURE(bench_incircle, plain_inline_random, plain_incircle, Inputs::random);
BENCHMARK_CAPTURE(bench_incircle, plain_call_random, incircle_inexact_call, Inputs::random);
BENCHMARK_CAPTURE(bench_incircle, exact_random, pear::incircle, Inputs::random);
BENCHMARK_CAPTURE(bench_incircle, exact_near_cocircular, pear::incircle, Inputs::near_degenerate);
BENCHMARK_CAPTURE(bench_incircle, exact_cocircular_inexact_differences, pear::incircle,
                  Inputs::degenerate);

}  // namespace

BENCHMARK_MAIN();
