#include "progress_display.hpp"

#include <unistd.h>

#include <cstdio>

#include <fmt/format.h>

namespace hyst::cli {
namespace {

// A terminal is redrawn at most this often (the last report of a run is always drawn).
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
// The ticker of a step without a count redraws its elapsed time this often.
constexpr auto kTickInterval = std::chrono::milliseconds(500);

std::string seconds_text(double seconds) {
  if (seconds < 60.0) return fmt::format("{:.1f} s", seconds);
  const auto whole = static_cast<long long>(seconds + 0.5);
  return fmt::format("{} min {:02} s", whole / 60, whole % 60);
}

}  // namespace

ProgressMode ProgressFlags::mode() const {
  if (quiet) return ProgressMode::never;
  return progress ? ProgressMode::always : ProgressMode::automatic;
}

void add_progress_flags(CLI::App& command, ProgressFlags& flags) {
  auto* progress = command.add_flag(
      "--progress", flags.progress,
      "Report progress on standard error also when it is not a terminal (one line per step)");
  auto* quiet = command.add_flag("--quiet", flags.quiet, "No progress report, also on a terminal");
  progress->excludes(quiet);
}

ProgressDisplay::ProgressDisplay(std::string command, ProgressMode mode)
    : command_(std::move(command)),
      terminal_(::isatty(::fileno(stderr)) == 1),
      start_(std::chrono::steady_clock::now()) {
  enabled_ = mode == ProgressMode::always || (mode == ProgressMode::automatic && terminal_);
}

ProgressDisplay::~ProgressDisplay() {
  stop_ticker(true);
  const std::lock_guard lock(mutex_);
  if (line_open_) std::fputs("\n", stderr);
}

double ProgressDisplay::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressDisplay::write_line(const std::string& text, bool final) {
  if (terminal_) {
    // Redrawn in place: back to the line start, the text, the rest of the old line cleared.
    fmt::print(stderr, "\r{}: {}\x1b[K", command_, text);
    line_open_ = !final;
    if (final) std::fputs("\n", stderr);
  } else {
    fmt::print(stderr, "{}: {}\n", command_, text);
  }
  std::fflush(stderr);
}

ProgressCallback ProgressDisplay::callback() {
  if (!enabled_) return {};
  return [this](const Progress& progress) { draw(progress); };
}

void ProgressDisplay::draw(const Progress& progress) {
  const std::lock_guard lock(mutex_);
  const bool final = progress.done >= progress.total;
  const auto now = std::chrono::steady_clock::now();
  if (terminal_ && !final && progress.done > 0 && now - last_draw_ < kRedrawInterval) return;
  last_draw_ = now;
  const double seconds = elapsed();
  if (ticking_) {  // the counted parts of the step the ticker shows (a fit's starts)
    detail_ = fmt::format("{}/{} {}", progress.done, progress.total, progress.task);
    if (!final && !progress.current.empty()) detail_ += fmt::format(", now {}", progress.current);
    write_line(fmt::format("{}: {}; {} elapsed", ticker_text_, detail_, seconds_text(seconds)),
               false);
    return;
  }
  std::string text = fmt::format("{}/{} {}", progress.done, progress.total, progress.task);
  if (!final && !progress.current.empty()) text += fmt::format(", now {}", progress.current);
  text += fmt::format("; {} elapsed", seconds_text(seconds));
  if (!final && progress.done > 0) {
    const double left = seconds / static_cast<double>(progress.done) *
                        static_cast<double>(progress.total - progress.done);
    text += fmt::format(", about {} left", seconds_text(left));
  }
  write_line(text, final);
}

void ProgressDisplay::start_ticker(std::string_view what) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  ticker_text_ = std::string(what);
  detail_.clear();
  ticking_ = true;
  write_line(fmt::format("{} ...", ticker_text_), false);
  if (!terminal_) return;  // a pipe gets the start and the end line only
  ticker_ = std::thread([this] {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, kTickInterval, [this] { return !ticking_; })) {
      write_line(fmt::format("{}{}{}; {} elapsed", ticker_text_, detail_.empty() ? "" : ": ",
                             detail_, seconds_text(elapsed())),
                 false);
    }
  });
}

void ProgressDisplay::stop_ticker(bool failed) {
  {
    const std::lock_guard lock(mutex_);
    if (!ticking_) return;
    ticking_ = false;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
  const std::lock_guard lock(mutex_);
  write_line(fmt::format("{}: {} after {}", ticker_text_, failed ? "stopped" : "done",
                         seconds_text(elapsed())),
             true);
}

}  // namespace hyst::cli
