// pear: a small work-stealing scheduler, usable on its own (no OpenMP, no global state beyond
// the lazily created default executor).
//
//   pear::Executor executor(4);                 // 4 = 3 worker threads + the thread that waits
//
//   pear::TaskGroup group(executor);            // "run these k closures in parallel and wait"
//   for (auto& part : parts) group.run([&part] { part.solve(); });
//   group.wait();                               // helps; rethrows the first exception
//
//   pear::TaskGraph graph;                      // build once, run many times
//   auto load = graph.emplace([&] { load_rings(); });
//   auto clip = graph.emplace([&](std::stop_token stop) { clip_ears(stop); });
//   load.precede(clip);
//   executor.run(graph).wait();
//
//   pear::parallel_for(executor, 0, n, 1024, [&](int i) { out[i] = f(in[i]); });
//   double sum = pear::parallel_reduce(executor, 0, n, 1024, 0.0,
//                                      [&](int i) { return in[i]; }, std::plus<>());
//
// Semantics, in short (docs/scheduler.md has the design):
// - An executor of concurrency N runs N - 1 worker threads; the Nth is whichever thread waits
//   (TaskGroup::wait, Future::wait, parallel_for...). N = 1 runs everything on the waiting thread.
// - A waiting thread never blocks while there is work it can take: it runs other tasks, so nested
//   parallelism cannot deadlock. Idle threads spin briefly, then sleep; an idle pool uses no CPU.
// - The first exception thrown by a task is rethrown by wait(); tasks not yet started are then
//   skipped (cancelled), and the std::stop_token handed to tasks that take one is triggered.
// - Destroying an executor cancels graph runs still in flight, drains them and joins its threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <stop_token>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "pear/config.hpp"
#include "pear/detail/scheduler.hpp"
#include "pear/export.hpp"

#if !PEAR_HAS_THREADS
#error "this pear was built with -Dthreads=disabled: it has no scheduler (pear/config.hpp)"
#endif

namespace pear {

class Executor;
class TaskGraph;
class Future;

/// Tasks run on N - 1 worker threads plus the waiting thread. Thread-safe; share one across
/// many triangulations. Must not be destroyed from one of its own tasks.
class PEAR_API Executor {
 public:
  /// concurrency = how many threads run tasks at once, >= 1 (0 is taken as 1). Throws
  /// std::invalid_argument above 4096, std::system_error when a thread cannot be started.
  explicit Executor(std::size_t concurrency = std::thread::hardware_concurrency());
  /// Cancels graph runs still in flight, finishes draining them, joins every worker thread.
  ~Executor();
  Executor(const Executor&) = delete;
  Executor& operator=(const Executor&) = delete;

  std::size_t concurrency() const noexcept;

  /// Starts one run of graph. The graph must outlive the run and not change during it; runs
  /// of one graph may overlap. Throws std::invalid_argument when the graph has a cycle. Stop
  /// requests on stop cancel the run (tasks not yet started are skipped).
  Future run(const TaskGraph& graph, std::stop_token stop = {});

 private:
  friend detail::ExecutorImpl& detail::impl_of(Executor&) noexcept;
  std::unique_ptr<detail::ExecutorImpl> impl_;
};

/// The executor pear uses when given none: created on first use with hardware_concurrency().
PEAR_API Executor& default_executor();
/// The executor whose task or wait this thread is in, else default_executor().
PEAR_API Executor& current_executor();

/// The result of Executor::run. Move-only; the destructor waits (without rethrowing).
class PEAR_API Future {
 public:
  Future() = default;
  explicit Future(std::shared_ptr<detail::RunState> state) : state_(std::move(state)) {}
  Future(Future&&) noexcept = default;
  Future& operator=(Future&& other) noexcept;
  ~Future();

  /// Waits for the run, helping with its work meanwhile; rethrows the first task exception.
  void wait() const;
  /// True once every task has run or been skipped.
  bool ready() const noexcept;
  /// Requests a stop: tasks not yet started are skipped. Then wait() as usual.
  void cancel() const noexcept;
  /// After ready(): whether some task was skipped because of a stop or an exception.
  bool cancelled() const noexcept;

 private:
  std::shared_ptr<detail::RunState> state_;
};

/// A set of closures that run in parallel; wait() waits for all of them. run() may be called
/// from the group's own tasks (recursive spawning). Create and destroy it on one thread, as a
/// scoped object. The destructor cancels what has not started and waits.
class PEAR_API TaskGroup {
 public:
  explicit TaskGroup(Executor& executor = current_executor(), std::stop_token stop = {});
  ~TaskGroup();
  TaskGroup(const TaskGroup&) = delete;
  TaskGroup& operator=(const TaskGroup&) = delete;

  /// Schedules task(), or task(stop_token) when it takes one.
  template <class F>
  void run(F&& task) {
    auto* job = new Closure<std::decay_t<F>>(this, std::forward<F>(task));
    pending_.add(1);
    spawn(owner_, job);
  }

  /// Runs other tasks until all of this group's have finished; then rethrows the first
  /// exception one of them threw. After an exception or cancel() the group stays cancelled.
  void wait();
  /// Tasks not yet started are skipped; stop tokens handed to tasks are triggered.
  void cancel() noexcept;
  bool cancelled() const noexcept { return cancelled_.load(std::memory_order_acquire); }
  /// The token tasks get: triggered by cancel(), an exception, or the stop token given.
  std::stop_token stop_token();

 private:
  template <class F>
  struct Closure : TaskJob {
    template <class G>
    Closure(TaskGroup* owner, G&& fn)
        : TaskJob{&Closure::execute}, group(owner), task(std::forward<G>(fn)) {}
    static void execute(TaskJob* job) {
      auto* self = static_cast<Closure*>(job);
      TaskGroup& group = *self->group;
      if (!group.cancelled()) {
        try {
          if constexpr (std::is_invocable_v<F&, std::stop_token>) {
            self->task(group.stop_token());
          } else {
            self->task();
          }
        } catch (...) {
          group.fail(std::current_exception());
        }
      }
      delete self;  // captures die before wait() can return
      Executor& executor = group.owner_;
      if (group.pending_.arrive()) wake_waiters(executor);  // group may be gone now
    }
    TaskGroup* group;
    F task;
  };
  struct CancelOnStop {
    TaskGroup* group;
    void operator()() const noexcept { group->cancel(); }
  };

  void fail(std::exception_ptr error) noexcept;
  /// What the templates above need of the executor, exported as members (nothing in
  /// pear::detail is part of libpear's interface).
  static void spawn(Executor& executor, TaskJob* job) noexcept;
  static void wake_waiters(Executor& executor) noexcept;

  Executor& owner_;
  detail::ExecutorImpl& executor_;
  detail::ThreadScope scope_;
  detail::WaitCounter pending_;
  std::atomic<bool> cancelled_{false};
  std::atomic<bool> failed_{false};
  std::exception_ptr error_;
  std::atomic<std::stop_source*> stop_source_{nullptr};   // created on first stop_token()
  std::optional<std::stop_callback<CancelOnStop>> link_;  // last: deregistered first
};

/// Handle to a task of a TaskGraph (cheap to copy). Valid while the graph lives.
class PEAR_API Task {
 public:
  /// This task runs before each of others. Throws std::invalid_argument across graphs.
  template <std::same_as<Task>... Others>
  Task& precede(Others... others) {
    (add_edge(*this, others), ...);
    return *this;
  }
  /// This task runs after each of others.
  template <std::same_as<Task>... Others>
  Task& succeed(Others... others) {
    (add_edge(others, *this), ...);
    return *this;
  }
  /// Position in emplace order (0-based): what error messages name.
  std::size_t index() const noexcept { return index_; }

 private:
  friend class TaskGraph;
  Task(TaskGraph* graph, std::uint32_t index) : graph_(graph), index_(index) {}
  static void add_edge(Task from, Task to);
  TaskGraph* graph_;
  std::uint32_t index_;
};

/// A dependency graph of tasks: build once (emplace, precede), run many times.
class PEAR_API TaskGraph {
 public:
  TaskGraph() = default;
  TaskGraph(const TaskGraph&) = delete;
  TaskGraph& operator=(const TaskGraph&) = delete;

  /// Adds a task running task() or task(stop_token).
  /// Throws std::length_error beyond 2^32 - 1 tasks.
  template <class F>
  Task emplace(F&& task) {
    if (nodes_.size() >= 0xffffffffu) throw_too_many();
    nodes_.push_back(Node{detail::TaskBody(std::forward<F>(task)), {}, 0});
    checked_.store(false, std::memory_order_relaxed);
    return Task(this, static_cast<std::uint32_t>(nodes_.size() - 1));
  }
  std::size_t size() const noexcept { return nodes_.size(); }
  bool empty() const noexcept { return nodes_.empty(); }

 private:
  friend class Task;
  friend class Executor;
  friend struct detail::RunState;
  struct Node {
    detail::TaskBody body;
    std::vector<std::uint32_t> successors;
    std::uint32_t predecessors;
  };
  /// Throws std::invalid_argument naming a task on a cycle; cached until the graph changes.
  void check_acyclic() const;
  std::uint32_t task_on_cycle(const std::vector<std::uint32_t>& pending) const;
  [[noreturn]] static void throw_too_many();

  std::vector<Node> nodes_;
  mutable std::atomic<bool> checked_{false};
};

namespace detail {
template <class I>
std::size_t auto_grain(I count, std::size_t concurrency) {
  return std::max<std::size_t>(1, static_cast<std::size_t>(count) / (8 * concurrency));
}

template <class I, class Body>
void split_for(TaskGroup& group, I begin, I end, std::size_t grain, Body& body) {
  // Halve until grain: thieves take the big halves near the top of the deque.
  while (static_cast<std::size_t>(end - begin) > grain) {
    const I middle = begin + (end - begin) / 2;
    group.run([&group, &body, middle, end, grain] { split_for(group, middle, end, grain, body); });
    end = middle;
  }
  for (I i = begin; i < end; ++i) body(i);
}
}  // namespace detail

/// body(i) for every i in [begin, end), in chunks of about grain (0: chosen from the size and
/// the concurrency). Rethrows the first exception a body threw; the rest is then skipped.
template <std::integral I, class Body>
void parallel_for(Executor& executor, I begin, I end, std::size_t grain, Body&& body) {
  if (end <= begin) return;
  if (grain == 0) grain = detail::auto_grain(end - begin, executor.concurrency());
  if (executor.concurrency() == 1 || static_cast<std::size_t>(end - begin) <= grain) {
    for (I i = begin; i < end; ++i) body(i);
    return;
  }
  TaskGroup group(executor);
  detail::split_for(group, begin, end, grain, body);
  group.wait();
}

template <std::integral I, class Body>
void parallel_for(I begin, I end, std::size_t grain, Body&& body) {
  parallel_for(current_executor(), begin, end, grain, std::forward<Body>(body));
}

/// Folds combine(acc, map(i)) over [begin, end): chunks of grain (0: automatic) are folded from
/// identity in index order, then the chunk results in chunk order. So the result depends only on
/// the grain, never on the thread count or timing (give a grain to make it fully deterministic).
template <std::integral I, class T, class Map, class Combine>
T parallel_reduce(Executor& executor, I begin, I end, std::size_t grain, T identity, Map map,
                  Combine combine) {
  if (end <= begin) return identity;
  if (grain == 0) grain = detail::auto_grain(end - begin, executor.concurrency());
  const std::size_t count = static_cast<std::size_t>(end - begin);
  const std::size_t chunks = (count + grain - 1) / grain;
  std::vector<std::optional<T>> partial(chunks);
  parallel_for(executor, std::size_t{0}, chunks, 1, [&](std::size_t chunk) {
    const I first = static_cast<I>(begin + static_cast<I>(chunk * grain));
    const I last = static_cast<I>(first + static_cast<I>(std::min(grain, count - chunk * grain)));
    T acc = identity;
    for (I i = first; i < last; ++i) acc = combine(std::move(acc), map(i));
    partial[chunk].emplace(std::move(acc));
  });
  T result = std::move(identity);
  for (auto& p : partial) result = combine(std::move(result), std::move(*p));
  return result;
}

template <std::integral I, class T, class Map, class Combine>
T parallel_reduce(I begin, I end, std::size_t grain, T identity, Map map, Combine combine) {
  return parallel_reduce(current_executor(), begin, end, grain, std::move(identity), std::move(map),
                         std::move(combine));
}

/// Runs the given closures in parallel and waits; rethrows the first exception.
template <class... F>
void parallel_invoke(Executor& executor, F&&... tasks) {
  TaskGroup group(executor);
  (group.run(std::forward<F>(tasks)), ...);
  group.wait();
}

}  // namespace pear
