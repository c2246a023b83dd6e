#pragma once
// Progress of long commands (fit, compare, actuator compare, the demo) on standard error: redrawn
// in place when standard error is a terminal, nothing in a pipe or file unless asked for
// (--progress: one line per step), never with --quiet. Standard output, where the results go, is
// left alone.

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

#include <CLI/CLI.hpp>

#include "hyst/core/progress.hpp"

namespace hyst::cli {

enum class ProgressMode { automatic, always, never };

//! The --progress and --quiet flags of a command (they exclude each other).
struct ProgressFlags {
  bool progress = false;
  bool quiet = false;
  ProgressMode mode() const;
};
void add_progress_flags(CLI::App& command, ProgressFlags& flags);

class ProgressDisplay {
 public:
  //! `command` prefixes every line, e.g. "hyst compare".
  ProgressDisplay(std::string command, ProgressMode mode);
  ~ProgressDisplay();
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;

  bool enabled() const { return enabled_; }
  //! Draws each report of a counted run ("3/16 models, now gpi; 4.2 s elapsed, about 18 s
  //! left"); empty when the display is off.
  ProgressCallback callback();
  //! Runs `work` while `what` (e.g. "fitting gpi") is shown with the elapsed time, and with the
  //! counts that callback() gets meanwhile (a fit's starts); returns what `work` returns.
  template <class Work>
  auto run(std::string_view what, Work&& work) {
    start_ticker(what);
    struct Stop {
      ProgressDisplay* display;
      int exceptions = std::uncaught_exceptions();
      ~Stop() { display->stop_ticker(std::uncaught_exceptions() > exceptions); }
    } stop{this};
    return work();
  }

 private:
  void draw(const Progress& progress);
  void start_ticker(std::string_view what);
  void stop_ticker(bool failed);
  void write_line(const std::string& text, bool final);
  double elapsed() const;

  std::string command_;
  bool enabled_ = false;
  bool terminal_ = false;
  bool line_open_ = false;  // a line redrawn in place is on the terminal
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_{};
  std::mutex mutex_;
  std::condition_variable wake_;
  bool ticking_ = false;
  std::string ticker_text_;
  std::string detail_;  // the last count told during the ticker's step
  std::thread ticker_;
};

}  // namespace hyst::cli
