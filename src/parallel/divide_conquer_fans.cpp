#include "divide_conquer_fans.hpp"

#include <algorithm>

#include "geometry/sort.hpp"

namespace pear::detail {
namespace {

constexpr std::uint32_t no_slot = UINT32_MAX;

}  // namespace

void FanReducer::add(const std::array<std::uint32_t, 3>& t, TriangleList& local) {
  const auto id = static_cast<std::uint32_t>(local.size());
  local.push_back(t);
  dead_.push_back(0);
  for (std::uint32_t v : t)
    if (slot_[v] != no_slot) incident_[slot_[v]].push_back(id);
}

void FanReducer::reduce(const Boundary& piece, const PieceCorner* corners, std::uint32_t count,
                        TriangleList& local) {
  slot_.assign(count, no_slot);
  std::uint32_t slots = 0;
  for (std::uint32_t i = 0; i < count; ++i)
    if (is_steiner(corners[i])) slot_[i] = slots++;
  if (slots == 0) return;
  if (incident_.size() < slots) incident_.resize(slots);
  for (std::uint32_t k = 0; k < slots; ++k) incident_[k].clear();
  dead_.assign(local.size(), 0);
  for (std::uint32_t id = 0; id < local.size(); ++id)
    for (std::uint32_t v : local[id])
      if (slot_[v] != no_slot) incident_[slot_[v]].push_back(id);
  for (std::uint32_t s = 0; s < count; ++s)
    if (slot_[s] != no_slot && fan_path(s, count, local)) clip_fan(s, piece, local);
  std::size_t alive = 0;
  for (std::size_t id = 0; id < local.size(); ++id)
    if (!dead_[id]) local[alive++] = local[id];
  local.resize(alive);
}

/// The fan's outer chain, from s's successor to its predecessor (counterclockwise around s).
bool FanReducer::fan_path(std::uint32_t s, std::uint32_t count, const TriangleList& local) {
  fan_.clear();
  links_.clear();
  for (std::uint32_t id : incident_[slot_[s]]) {
    if (dead_[id]) continue;
    const auto& t = local[id];
    const int k = t[0] == s ? 0 : t[1] == s ? 1 : 2;
    links_.push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
    fan_.push_back(id);
  }
  if (links_.size() < 2) return false;
  detail::sort(links_.begin(), links_.end());
  path_.assign(1, s + 1 == count ? 0 : s + 1);
  for (std::size_t step = 0; step < links_.size(); ++step) {
    const auto it = std::lower_bound(links_.begin(), links_.end(), std::pair{path_.back(), 0u});
    if (it == links_.end() || it->first != path_.back()) return false;
    if (it + 1 != links_.end() && (it + 1)->first == it->first) return false;
    path_.push_back(it->second);
  }
  return path_.back() == (s == 0 ? count - 1 : s - 1);
}

/// Clips the convex vertices of the chain with a stack (Graham-scan style, linear time); s
/// keeps one triangle per edge of what is left.
void FanReducer::clip_fan(std::uint32_t s, const Boundary& piece, TriangleList& local) {
  const std::size_t before = local.size();
  stack_.clear();
  for (std::uint32_t v : path_) {
    stack_.push_back(v);
    while (stack_.size() >= 3) {
      const std::size_t n = stack_.size();
      const std::uint32_t a = stack_[n - 3], b = stack_[n - 2], c = stack_[n - 1];
      if (!(orient2d(piece.pos[a], piece.pos[b], piece.pos[c]) > 0)) break;
      add({a, b, c}, local);
      stack_[n - 2] = c;
      stack_.pop_back();
    }
  }
  if (local.size() == before) return;
  for (std::uint32_t id : fan_) dead_[id] = 1;
  for (std::size_t k = 0; k + 1 < stack_.size(); ++k) add({s, stack_[k], stack_[k + 1]}, local);
}

}  // namespace pear::detail
