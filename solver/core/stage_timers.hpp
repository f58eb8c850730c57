// Wall-clock time per pipeline stage (fluid predictor, IB forcing, projection, bodies, output),
// so benchmarks and the report can show that a scene pays only for the stages it runs.
#pragma once
#include <array>
#include <chrono>
#include <string_view>

namespace ibms {

// The steps of docs/method.md §7 by the same names: schedules (1), predictor (2, the fluid's part),
// projection (3), bodies (6); ib_forcing is the immersed-boundary work of steps 2 and 4 (the
// prediction's force, the slip and its corrections); the clock (5) is not timed; diagnostics and
// output follow the step.
// `contacts` (DEM forces incl. the CDS pair search, once per solid sub-step) runs inside `bodies`,
// so its time is also part of the bodies time.
enum class Stage { schedules, predictor, ib_forcing, projection, bodies, diagnostics, output, contacts, count };

inline constexpr std::array<std::string_view, static_cast<int>(Stage::count)> stage_names{
    "schedules", "predictor", "ib_forcing", "projection", "bodies", "diagnostics", "output", "contacts"};

class StageTimers {
 public:
  class Scope {
   public:
    Scope(StageTimers& timers, Stage stage)
        : timers_(timers), stage_(stage), start_(std::chrono::steady_clock::now()) {}
    ~Scope() {
      timers_.seconds_[static_cast<int>(stage_)] +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      timers_.calls_[static_cast<int>(stage_)] += 1;
    }
   private:
    StageTimers& timers_;
    Stage stage_;
    std::chrono::steady_clock::time_point start_;
  };
  Scope time(Stage stage) { return Scope(*this, stage); }
  // Adds time measured elsewhere (e.g. on another thread, under the caller's lock).
  void add(Stage stage, double seconds, long calls) {
    seconds_[static_cast<int>(stage)] += seconds;
    calls_[static_cast<int>(stage)] += calls;
  }
  double seconds(Stage stage) const { return seconds_[static_cast<int>(stage)]; }
  long calls(Stage stage) const { return calls_[static_cast<int>(stage)]; }

 private:
  std::array<double, static_cast<int>(Stage::count)> seconds_{};
  std::array<long, static_cast<int>(Stage::count)> calls_{};
};

}  // namespace ibms
