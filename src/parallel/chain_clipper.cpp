#include "chain_clipper.hpp"

#include "../earclip/ear_test.hpp"

namespace pear::detail {

namespace {

/// Foreign entries one ear test may look at. The start grids keep what other chains have
/// clipped since the phase began, so a big triangle late in a chain's work would look at many
/// dead nodes; such an ear is left to the next round or the sequential finish, with a fresh grid.
constexpr int foreign_budget = 48;

}  // namespace

bool ChainClipper::is_ear(std::uint32_t v) const {
  const auto near = [this](const Point& a, const Point& t, const Point& c, auto&& visit) {
    if (own_grid_.any_near_triangle(a, t, c, visit)) return true;
    int looked_at = 0;
    return s_->any_foreign_near(a, t, c, chain_, [&](const ReflexGrid::Entry& e) {
      return ++looked_at > foreign_budget || visit(e);
    });
  };
  return detail::is_ear(*s_->b, OwnLinks{s_, chain_}, v, near);
}

void ChainClipper::offer(std::uint32_t v) {
  const Boundary& b = *s_->b;
  const std::uint32_t p = b.prev[v], n = b.next[v];
  if (!own(p) || !own(n)) return;
  // Where rings touch (pinches) the sequential engine dissolves the spikes that clipping leaves
  // and falls back when it must; leave those places to it.
  if (s_->pinch[p] || s_->pinch[v] || s_->pinch[n]) return;
  if (!is_ear(v)) return;
  queue_.push(ear_bucket(b, v, heuristic_), {v, s_->stamp[v]});
}

void ChainClipper::unhash(std::uint32_t v) {
  if (!s_->hashed[v]) return;
  s_->hashed[v] = 0;
  own_grid_.remove(v, s_->b->pos[v]);
}

void ChainClipper::update(std::uint32_t v) {
  if (s_->hashed[v] && !s_->pinch[v] && s_->b->turn(v) >= 0) unhash(v);
  ++s_->stamp[v];
}

void ChainClipper::run(SharedBoundary& s, std::uint32_t chain, std::size_t first, std::size_t last,
                       EarHeuristic heuristic, TriangleList& out) {
  s_ = &s;
  chain_ = chain;
  heuristic_ = heuristic;
  queue_.clear();
  Boundary& b = *s.b;
  const std::size_t count = s.order.size();
  scratch_.clear();
  for (std::size_t i = (first + 1) % count; i != last; i = (i + 1) % count)
    if (s.hashed[s.order[i]]) scratch_.push_back(s.order[i]);
  own_grid_.build(b, scratch_);
  for (std::size_t i = (first + 1) % count; i != last; i = (i + 1) % count) offer(s.order[i]);
  EarQueue::Candidate top;
  while (queue_.pop(top)) {
    const std::uint32_t v = top.node;
    if (!s.alive[v] || s.stamp[v] != top.stamp) continue;
    const std::uint32_t p = b.prev[v], n = b.next[v];
    out.push_back({b.vertex[p], b.vertex[v], b.vertex[n]});
    b.unlink(v);
    s.alive[v] = 0;
    unhash(v);
    update(p);
    update(n);
    offer(n);
    offer(p);
  }
}

}  // namespace pear::detail
