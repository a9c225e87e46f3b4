// Where a stage's parallel tasks go. The stages know only this interface: the pipeline
// implements it on pear's scheduler in a threaded build, and without threads every task runs
// on the calling thread (RunContext::runner is then null): no stage needs a thread library.
#pragma once

#include <cstddef>
#include <type_traits>

namespace pear::detail {

/// A non-owning reference to a callable taking a task index: no allocation, one indirect call.
class TaskFunction {
 public:
  template <class F>
  requires(!std::is_same_v<std::remove_cvref_t<F>, TaskFunction>)
      TaskFunction(F& task)  // NOLINT(google-explicit-constructor): a reference, like a span
      : object_(const_cast<void*>(static_cast<const void*>(&task))),
        call_([](void* object, std::size_t i) { (*static_cast<F*>(object))(i); }) {}
  void operator()(std::size_t i) const { call_(object_, i); }

 private:
  void* object_;
  void (*call_)(void*, std::size_t);
};

class TaskRunner {
 public:
  /// How many threads run tasks at once.
  virtual std::size_t concurrency() const = 0;
  /// Runs task(i) for every i in [0, count), in parallel, and returns when all are done;
  /// rethrows the first exception a task threw.
  virtual void run(std::size_t count, TaskFunction task) const = 0;

 protected:
  ~TaskRunner() = default;
};

}  // namespace pear::detail
