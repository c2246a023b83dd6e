#include "hyst/plot/gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <string_view>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "hyst/core/error.hpp"

extern char** environ;

namespace hyst::plot {
namespace {

namespace fs = std::filesystem;

std::string reason(int error_number) {
  return std::generic_category().message(error_number);
}

//! The series as it appears in messages: "series 2 ('model')".
std::string series_name(const Figure& figure, std::size_t index) {
  const auto& label = figure.series[index].label;
  return label.empty() ? fmt::format("series {}", index)
                       : fmt::format("series {} ('{}')", index, label);
}

void validate(const Figure& figure) {
  if (figure.width < 16 || figure.width > 20000 || figure.height < 16 || figure.height > 20000) {
    throw Error(fmt::format("figure size {} x {} pixels must be within 16..20000 on both sides",
                            figure.width, figure.height));
  }
  if (figure.series.empty()) throw Error("figure has no series to plot");
  for (std::size_t s = 0; s < figure.series.size(); ++s) {
    const auto& series = figure.series[s];
    if (series.x.size() != series.y.size()) {
      throw Error(fmt::format("{}: x has {} values but y has {}", series_name(figure, s),
                              series.x.size(), series.y.size()));
    }
    if (series.x.empty()) throw Error(fmt::format("{} has no points", series_name(figure, s)));
    const bool plain_colour = std::all_of(series.color.begin(), series.color.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '#' || c == '-';
    });
    if (!plain_colour) {
      throw Error(fmt::format("{}: colour '{}' must be \"#rrggbb\" or a gnuplot colour name",
                              series_name(figure, s), series.color));
    }
    for (std::size_t k = 0; k < series.x.size(); ++k) {
      if (!std::isfinite(series.x[k])) {
        throw Error(
            fmt::format("{}: x[{}] = {} is not finite", series_name(figure, s), k, series.x[k]));
      }
      if (!std::isfinite(series.y[k])) {
        throw Error(
            fmt::format("{}: y[{}] = {} is not finite", series_name(figure, s), k, series.y[k]));
      }
    }
  }
}

//! A gnuplot single-quoted string: '' stands for ', nothing else is special. Line breaks and
//! other control characters would end the command, so they become spaces.
std::string gnuplot_string(std::string_view text) {
  std::string out = "'";
  for (const char c : text) {
    if (c == '\'') {
      out += "''";
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      out += ' ';
    } else {
      out += c;
    }
  }
  out += '\'';
  return out;
}

std::string_view style_clause(Series::Style style) {
  switch (style) {
    case Series::Style::points:
      return "with points pt 7 ps 0.6";
    case Series::Style::lines_points:
      return "with linespoints lw 1.5 pt 7 ps 0.6";
    case Series::Style::lines:
      break;
  }
  return "with lines lw 1.5";
}

enum class Format { png, svg };

std::string script_for(const Figure& figure, const fs::path& output, Format format) {
  std::string script;
  const auto size = fmt::format("size {},{}", figure.width, figure.height);
  if (format == Format::svg) {
    script +=
        fmt::format("set terminal svg noenhanced {} font 'sans,11' background rgb 'white'\n", size);
  } else {
    // pngcairo draws anti-aliased lines; the libgd `png` terminal is the fallback.
    script += fmt::format(
        "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {{\n"
        "  set terminal pngcairo noenhanced {0} font ',11'\n"
        "}} else {{\n"
        "  set terminal png noenhanced {0}\n"
        "}}\n",
        size);
  }
  script += fmt::format("set output {}\n", gnuplot_string(output.string()));
  if (!figure.title.empty()) script += fmt::format("set title {}\n", gnuplot_string(figure.title));
  if (!figure.x_label.empty())
    script += fmt::format("set xlabel {}\n", gnuplot_string(figure.x_label));
  if (!figure.y_label.empty())
    script += fmt::format("set ylabel {}\n", gnuplot_string(figure.y_label));
  script += "set grid\nset key top left box opaque\n";
  if (figure.equal_axes) script += "set size ratio -1\n";
  for (std::size_t s = 0; s < figure.series.size(); ++s) {
    const auto& series = figure.series[s];
    script += fmt::format("$d{} << EOD\n", s);
    for (std::size_t k = 0; k < series.x.size(); ++k) {
      script += fmt::format("{:.17g} {:.17g}\n", series.x[k], series.y[k]);
    }
    script += "EOD\n";
  }
  script += "plot ";
  for (std::size_t s = 0; s < figure.series.size(); ++s) {
    const auto& series = figure.series[s];
    if (s > 0) script += ", \\\n     ";
    script +=
        fmt::format("$d{} using 1:2 {}{} {}", s, style_clause(series.style),
                    series.color.empty() ? "" : " lc rgb " + gnuplot_string(series.color),
                    series.label.empty() ? "notitle" : "title " + gnuplot_string(series.label));
  }
  script += "\nunset output\n";
  return script;
}

//! Closes a descriptor on scope exit.
class Descriptor {
 public:
  explicit Descriptor(int fd = -1) : fd_(fd) {}
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() { reset(); }
  int get() const { return fd_; }
  void reset() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_;
};

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

//! posix_spawn file actions, destroyed on scope exit.
class FileActions {
 public:
  FileActions() {
    if (const int error = ::posix_spawn_file_actions_init(&actions_)) {
      throw Error(fmt::format("cannot start gnuplot: {}", reason(error)));
    }
  }
  FileActions(const FileActions&) = delete;
  FileActions& operator=(const FileActions&) = delete;
  ~FileActions() { ::posix_spawn_file_actions_destroy(&actions_); }
  posix_spawn_file_actions_t* get() { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_;
};

//! Starts `gnuplot <args>` with the given descriptors as standard input and error (standard
//! output goes to /dev/null); returns the process id or throws.
pid_t spawn_gnuplot(const std::vector<std::string>& args, int stdin_fd, int stderr_fd) {
  FileActions actions;
  int error = 0;
  if (stdin_fd >= 0) {
    error = ::posix_spawn_file_actions_adddup2(actions.get(), stdin_fd, STDIN_FILENO);
  } else {
    error =
        ::posix_spawn_file_actions_addopen(actions.get(), STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  }
  if (!error) {
    error =
        ::posix_spawn_file_actions_addopen(actions.get(), STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  }
  if (!error) {
    error = stderr_fd >= 0
                ? ::posix_spawn_file_actions_adddup2(actions.get(), stderr_fd, STDERR_FILENO)
                : ::posix_spawn_file_actions_addopen(actions.get(), STDERR_FILENO, "/dev/null",
                                                     O_WRONLY, 0);
  }
  if (error) throw Error(fmt::format("cannot start gnuplot: {}", reason(error)));

  std::vector<std::string> storage{"gnuplot"};
  storage.insert(storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& arg : storage)
    argv.push_back(arg.data());
  argv.push_back(nullptr);

  pid_t pid = 0;
  error = ::posix_spawnp(&pid, "gnuplot", actions.get(), nullptr, argv.data(), environ);
  if (error == ENOENT) {
    throw Error("gnuplot is not installed or not on the PATH (Debian package gnuplot-nox)");
  }
  if (error) throw Error(fmt::format("cannot start gnuplot: {}", reason(error)));
  return pid;
}

//! Waits for the process; returns its exit status, or 128 + signal number.
int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return 255;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 255;
}

//! Everything gnuplot wrote to standard error, condensed to one line: the lines that are not
//! blank and not just the '^' marker, joined with " | ", at most about 2000 characters.
std::string condensed(std::FILE* file) {
  std::rewind(file);
  std::string text;
  char buffer[4096];
  std::size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, file)) > 0)
    text.append(buffer, count);

  std::string out;
  std::size_t start = 0;
  while (start <= text.size()) {
    auto end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + start, end - start);
    const auto first = line.find_first_not_of(" \t\r^");
    if (first != std::string_view::npos) {
      line = line.substr(line.find_first_not_of(" \t"));
      while (!line.empty() && (line.back() == ' ' || line.back() == '\r'))
        line.remove_suffix(1);
      if (!out.empty()) out += " | ";
      out += line;
    }
    start = end + 1;
  }
  if (out.size() > 2000) out = out.substr(0, 2000) + " ...";
  return out;
}

//! Removes the file on scope exit unless released.
class RemoveOnExit {
 public:
  explicit RemoveOnExit(fs::path path) : path_(std::move(path)) {}
  RemoveOnExit(const RemoveOnExit&) = delete;
  RemoveOnExit& operator=(const RemoveOnExit&) = delete;
  ~RemoveOnExit() {
    if (!path_.empty()) ::unlink(path_.c_str());
  }
  void release() { path_.clear(); }

 private:
  fs::path path_;
};

fs::path temporary_path_for(const fs::path& path, Format format) {
  static std::atomic<unsigned long long> counter{0};
  const std::string target = path.filename().string().substr(0, 200);
  return path.parent_path() / fmt::format(".{}.tmp.{}.{}.{}", target,
                                          static_cast<long long>(::getpid()), counter.fetch_add(1),
                                          format == Format::svg ? "svg" : "png");
}

void check_folder(const fs::path& png) {
  if (png.filename().empty() || png.filename() == "." || png.filename() == "..") {
    throw Error(fmt::format("cannot write '{}': the path does not name a file", png.string()));
  }
  const fs::path folder = png.parent_path().empty() ? fs::path(".") : png.parent_path();
  std::error_code error;
  const auto status = fs::status(folder, error);
  if (!fs::exists(status)) {
    throw Error(fmt::format("cannot write '{}': the folder '{}' does not exist", png.string(),
                            folder.string()));
  }
  if (!fs::is_directory(status)) {
    throw Error(
        fmt::format("cannot write '{}': '{}' is not a folder", png.string(), folder.string()));
  }
}

}  // namespace

bool gnuplot_available() {
  try {
    return wait_for(spawn_gnuplot({"--version"}, -1, -1)) == 0;
  } catch (const Error&) {
    return false;
  }
}

namespace {

//! Renders the figure into `png` (an image file of the format, replaced atomically).
void write_image(const Figure& figure, const fs::path& png, Format format) {
  validate(figure);
  check_folder(png);

  const fs::path temporary = temporary_path_for(png, format);
  RemoveOnExit remove_temporary(temporary);
  const std::string script = script_for(figure, temporary, format);

  // gnuplot's standard error goes to an anonymous temporary file (read after it exits, so a
  // chatty gnuplot can never block on a full pipe while we are still writing the script).
  const std::unique_ptr<std::FILE, FileCloser> errors(std::tmpfile());
  if (!errors) throw Error(fmt::format("cannot start gnuplot: {}", reason(errno)));
  ::fcntl(::fileno(errors.get()), F_SETFD, FD_CLOEXEC);

  // A socket pair rather than a pipe: send(MSG_NOSIGNAL) reports EPIPE if gnuplot exits early,
  // instead of killing this process with SIGPIPE.
  int sockets[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0) {
    throw Error(fmt::format("cannot start gnuplot: {}", reason(errno)));
  }
  Descriptor ours(sockets[0]);
  Descriptor theirs(sockets[1]);
  const pid_t pid = spawn_gnuplot({}, theirs.get(), ::fileno(errors.get()));
  theirs.reset();

  std::string_view rest = script;
  while (!rest.empty()) {
    const ssize_t sent = ::send(ours.get(), rest.data(), rest.size(), MSG_NOSIGNAL);
    if (sent < 0) {
      if (errno == EINTR) continue;
      break;  // gnuplot stopped reading; its exit status and messages tell why
    }
    rest.remove_prefix(static_cast<std::size_t>(sent));
  }
  ours.reset();  // end of the script
  const int status = wait_for(pid);

  if (status != 0) {
    const auto messages = condensed(errors.get());
    throw Error(fmt::format("cannot write '{}': gnuplot failed (exit status {}){}{}", png.string(),
                            status, messages.empty() ? "" : ": ", messages));
  }
  std::error_code error;
  const auto size = fs::file_size(temporary, error);
  if (error || size == 0) {
    const auto messages = condensed(errors.get());
    throw Error(fmt::format("cannot write '{}': gnuplot wrote no image{}{}", png.string(),
                            messages.empty() ? "" : ": ", messages));
  }
  fs::rename(temporary, png, error);
  if (error) {
    throw Error(fmt::format("cannot write '{}': {} (renaming '{}' over it)", png.string(),
                            error.message(), temporary.string()));
  }
  remove_temporary.release();
}

}  // namespace

void write_png(const Figure& figure, const fs::path& png) {
  write_image(figure, png, Format::png);
}

void write_svg(const Figure& figure, const fs::path& svg) {
  write_image(figure, svg, Format::svg);
}

std::string svg_element(const Figure& figure) {
  const fs::path folder = fs::temp_directory_path();
  const fs::path file = temporary_path_for(folder / "figure.svg", Format::svg);
  RemoveOnExit remove_file(file);
  write_svg(figure, file);
  std::ifstream in(file, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto start = text.find("<svg");
  if (!in.good() && !in.eof()) throw Error("cannot read the SVG gnuplot wrote");
  if (start == std::string::npos) throw Error("gnuplot wrote no <svg> element");
  return text.substr(start);
}

}  // namespace hyst::plot
