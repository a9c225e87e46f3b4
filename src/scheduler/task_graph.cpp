// TaskGraph construction and its runs: per-run join counters, so one graph can run many times.
#include <stdexcept>
#include <string>

#include "executor_impl.hpp"

namespace pear::detail {

/// One task of one run: what the deques hold while a graph runs.
struct NodeJob : Job {
  RunState* run = nullptr;
  std::uint32_t index = 0;
  std::atomic<std::uint32_t> join{0};  // predecessors not yet finished in this run
};

struct RequestStop {
  std::stop_source* source;
  void operator()() const noexcept { source->request_stop(); }
};

struct RunState {
  RunState(ExecutorImpl& on, const TaskGraph& graph)
      : executor(on), nodes(graph.nodes_), jobs(new NodeJob[graph.nodes_.size()]) {}

  static void execute(Job* job);
  void run_node(std::uint32_t index);
  void finish();

  ExecutorImpl& executor;
  const std::vector<TaskGraph::Node>& nodes;
  std::unique_ptr<NodeJob[]> jobs;
  std::atomic<std::size_t> remaining{0};
  WaitCounter done;
  std::stop_source stop;
  std::stop_token token = stop.get_token();
  std::atomic<bool> failed{false};
  std::atomic<bool> skipped{false};
  std::exception_ptr error;
  std::optional<std::stop_callback<RequestStop>> link;  // the caller's stop token
  std::shared_ptr<RunState> self;                       // alive until the last task finishes
};

void RunState::execute(Job* job) {
  auto* current = static_cast<NodeJob*>(job);
  RunState& run = *current->run;
  for (;;) {
    run.run_node(current->index);
    // Release successors; keep one to run next on this thread (a loop, not recursion, so a
    // long chain does not grow the stack), push the others for thieves.
    NodeJob* next = nullptr;
    std::size_t pushed = 0;
    for (const std::uint32_t successor : run.nodes[current->index].successors) {
      NodeJob& ready = run.jobs[successor];
      // acq_rel: the last predecessor to finish sees all the others' effects, and so will
      // whoever runs the successor.
      if (ready.join.fetch_sub(1, std::memory_order_acq_rel) != 1) continue;
      if (next == nullptr) {
        next = &ready;
      } else {
        run.executor.push(&ready);
        ++pushed;
      }
    }
    if (pushed != 0) run.executor.gate.notify(pushed);
    if (run.remaining.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      run.finish();  // next is null here: every task has finished
      return;
    }
    if (next == nullptr) return;
    current = next;
  }
}

void RunState::run_node(std::uint32_t index) {
  if (token.stop_requested() || executor.shutting_down.load(std::memory_order_relaxed)) {
    skipped.store(true, std::memory_order_relaxed);
    return;
  }
  try {
    nodes[index].body(token);
  } catch (...) {
    if (!failed.exchange(true, std::memory_order_acq_rel)) error = std::current_exception();
    stop.request_stop();
  }
}

void RunState::finish() {
  const std::shared_ptr<RunState> keep = std::move(self);
  ExecutorImpl& on = executor;
  link.reset();
  if (done.arrive()) wake_waiters(on);
  if (on.runs_in_flight.arrive()) wake_waiters(on);
}

}  // namespace pear::detail

namespace pear {

Future Executor::run(const TaskGraph& graph, std::stop_token stop) {
  graph.check_acyclic();
  detail::ExecutorImpl& executor = *impl_;
  auto state = std::make_shared<detail::RunState>(executor, graph);
  const std::size_t count = graph.nodes_.size();
  if (count == 0) return Future(std::move(state));
  for (std::size_t i = 0; i < count; ++i) {
    detail::NodeJob& job = state->jobs[i];
    job.execute = &detail::RunState::execute;
    job.run = state.get();
    job.index = static_cast<std::uint32_t>(i);
    job.join.store(graph.nodes_[i].predecessors, std::memory_order_relaxed);
  }
  state->remaining.store(count, std::memory_order_relaxed);
  state->done.add(1);
  if (stop.stop_possible()) state->link.emplace(std::move(stop), detail::RequestStop{&state->stop});
  state->self = state;
  executor.runs_in_flight.add(1);
  std::size_t sources = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (graph.nodes_[i].predecessors != 0) continue;
    executor.push(&state->jobs[i]);
    ++sources;
  }
  executor.gate.notify(sources);
  return Future(std::move(state));
}

Future& Future::operator=(Future&& other) noexcept {
  if (this != &other) {
    Future old(std::move(*this));  // waits for our previous run
    state_ = std::move(other.state_);
  }
  return *this;
}

Future::~Future() {
  if (!state_ || state_->done.done()) return;
  try {
    detail::ThreadScope scope(state_->executor);
    state_->executor.help_until(state_->done);
  } catch (...) {  // a destructor must not throw; only locking can fail here
  }
}

void Future::wait() const {
  if (!state_) return;
  if (!state_->done.done()) {
    detail::ThreadScope scope(state_->executor);
    state_->executor.help_until(state_->done);
  }
  if (state_->failed.load(std::memory_order_acquire)) std::rethrow_exception(state_->error);
}

bool Future::ready() const noexcept {
  return !state_ || state_->done.done();
}

void Future::cancel() const noexcept {
  if (state_) state_->stop.request_stop();
}

bool Future::cancelled() const noexcept {
  return state_ && state_->skipped.load(std::memory_order_acquire);
}

void Task::add_edge(Task from, Task to) {
  if (from.graph_ != to.graph_) {
    throw std::invalid_argument("pear::Task::precede: task " + std::to_string(from.index_) +
                                " and task " + std::to_string(to.index_) +
                                " belong to different graphs");
  }
  auto& nodes = from.graph_->nodes_;
  nodes[from.index_].successors.push_back(to.index_);
  ++nodes[to.index_].predecessors;
  from.graph_->checked_.store(false, std::memory_order_relaxed);
}

void TaskGraph::throw_too_many() {
  throw std::length_error("pear::TaskGraph: more than 2^32 - 1 tasks");
}

void TaskGraph::check_acyclic() const {
  if (checked_.load(std::memory_order_acquire)) return;
  // Kahn's algorithm: a graph is acyclic iff repeatedly removing tasks without pending
  // predecessors removes them all.
  const std::size_t count = nodes_.size();
  std::vector<std::uint32_t> pending(count);
  std::vector<std::uint32_t> ready;
  for (std::size_t i = 0; i < count; ++i) {
    pending[i] = nodes_[i].predecessors;
    if (pending[i] == 0) ready.push_back(static_cast<std::uint32_t>(i));
  }
  std::size_t removed = 0;
  while (!ready.empty()) {
    const std::uint32_t task = ready.back();
    ready.pop_back();
    ++removed;
    for (const std::uint32_t successor : nodes_[task].successors) {
      if (--pending[successor] == 0) ready.push_back(successor);
    }
  }
  if (removed != count) {
    throw std::invalid_argument("pear::TaskGraph: task " + std::to_string(task_on_cycle(pending)) +
                                " is on a dependency cycle; the graph cannot run");
  }
  checked_.store(true, std::memory_order_release);
}

std::uint32_t TaskGraph::task_on_cycle(const std::vector<std::uint32_t>& pending) const {
  // Every task Kahn left has a predecessor it also left, so walking predecessors from any of
  // them for `count` steps must end on a cycle.
  const std::size_t count = nodes_.size();
  std::vector<std::uint32_t> left_predecessor(count, 0xffffffffu);
  for (std::size_t i = 0; i < count; ++i) {
    if (pending[i] == 0) continue;
    for (const std::uint32_t successor : nodes_[i].successors) {
      left_predecessor[successor] = static_cast<std::uint32_t>(i);
    }
  }
  std::uint32_t task = 0;
  while (pending[task] == 0) ++task;
  for (std::size_t step = 0; step < count; ++step) task = left_predecessor[task];
  return task;
}

}  // namespace pear
