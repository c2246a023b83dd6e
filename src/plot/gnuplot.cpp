#include "hyst/plot/gnuplot.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string_view>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "gnuplot_render.hpp"
#include "hyst/core/error.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/output_paths.hpp"

extern char** environ;

namespace hyst::plot {
namespace {

namespace fs = std::filesystem;

//! The series as it appears in messages: "series 2 ('model')".
std::string series_name(const Figure& figure, std::size_t index) {
  const auto& label = figure.series[index].label;
  return label.empty() ? fmt::format("series {}", index)
                       : fmt::format("series {} ('{}')", index, label);
}

void validate(const Figure& figure) {
  detail::check_size(figure.width, figure.height);
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

using detail::gnuplot_string;

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

using Format = detail::ImageFormat;

std::string script_for(const Figure& figure, const fs::path& output, Format format) {
  std::string script = detail::terminal_commands(figure.width, figure.height, format, output);
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

//! The gnuplot program on the PATH, found before fork() so that the child only has to exec it.
std::string find_gnuplot() {
  const char* path = std::getenv("PATH");
  const std::string_view folders = path != nullptr ? path : "/usr/local/bin:/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= folders.size()) {
    const auto end = std::min(folders.find(':', start), folders.size());
    const auto folder = folders.substr(start, end - start);
    const std::string candidate = fmt::format("{}/gnuplot", folder.empty() ? "." : folder);
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  throw Error("gnuplot is not installed or not on the PATH (Debian package gnuplot-nox)");
}

//! Starts `gnuplot <args>` with the given descriptors as standard input, output and error (-1:
//! /dev/null); returns the process id or throws. The child is killed when this process dies, so
//! that a killed hyst leaves no gnuplot behind still writing (PR_SET_PDEATHSIG).
pid_t spawn_gnuplot(const std::vector<std::string>& args, int stdin_fd, int stdout_fd,
                    int stderr_fd) {
  const std::string program = find_gnuplot();
  std::vector<std::string> storage{"gnuplot"};
  storage.insert(storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& arg : storage)
    argv.push_back(arg.data());
  argv.push_back(nullptr);

  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw Error(fmt::format("cannot start gnuplot: {}", errno_message(errno)));
  if (pid == 0) {
    // Only async-signal-safe calls from here on (the parent may have other threads).
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);  // the parent died before prctl()
    const int null_fd = ::open("/dev/null", O_RDWR);
    if (null_fd < 0) ::_exit(127);
    if (::dup2(stdin_fd >= 0 ? stdin_fd : null_fd, STDIN_FILENO) < 0 ||
        ::dup2(stdout_fd >= 0 ? stdout_fd : null_fd, STDOUT_FILENO) < 0 ||
        ::dup2(stderr_fd >= 0 ? stderr_fd : null_fd, STDERR_FILENO) < 0) {
      ::_exit(127);
    }
    ::execve(program.c_str(), argv.data(), environ);
    ::_exit(127);
  }
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

}  // namespace

std::string detail::gnuplot_string(std::string_view text) {
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

void detail::check_size(int width, int height) {
  if (width < 16 || width > 20000 || height < 16 || height > 20000) {
    throw Error(fmt::format("figure size {} x {} pixels must be within 16..20000 on both sides",
                            width, height));
  }
}

std::string detail::terminal_commands(int width, int height, ImageFormat format,
                                      const fs::path& output) {
  std::string script;
  const auto size = fmt::format("size {},{}", width, height);
  if (format == ImageFormat::svg) {
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
  // No file name: the image goes to standard output.
  script += output.empty() ? std::string("set output\n")
                           : fmt::format("set output {}\n", gnuplot_string(output.string()));
  return script;
}

bool gnuplot_available() {
  try {
    return wait_for(spawn_gnuplot({"--version"}, -1, -1, -1)) == 0;
  } catch (const Error&) {
    return false;
  }
}

namespace {

//! Runs gnuplot on the script, the image going to `output` (a file the script names) or, when
//! it is empty, to `stdout_fd`. `shown` names the destination in messages.
void render(const std::string& script, const fs::path& output, int stdout_fd,
            const fs::path& shown) {
  // gnuplot's standard error goes to an anonymous temporary file (read after it exits, so a
  // chatty gnuplot can never block on a full pipe while we are still writing the script).
  const std::unique_ptr<std::FILE, FileCloser> errors(std::tmpfile());
  if (!errors) throw Error(fmt::format("cannot start gnuplot: {}", errno_message(errno)));
  ::fcntl(::fileno(errors.get()), F_SETFD, FD_CLOEXEC);

  // A socket pair rather than a pipe: send(MSG_NOSIGNAL) reports EPIPE if gnuplot exits early,
  // instead of killing this process with SIGPIPE.
  int sockets[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0) {
    throw Error(fmt::format("cannot start gnuplot: {}", errno_message(errno)));
  }
  Descriptor ours(sockets[0]);
  Descriptor theirs(sockets[1]);
  const pid_t pid = spawn_gnuplot({}, theirs.get(), stdout_fd, ::fileno(errors.get()));
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
    throw Error(fmt::format("cannot write '{}': gnuplot failed (exit status {}){}{}",
                            shown.string(), status, messages.empty() ? "" : ": ", messages));
  }
  std::error_code error;
  const auto size = output.empty() ? static_cast<std::uintmax_t>(::lseek(stdout_fd, 0, SEEK_END))
                                   : fs::file_size(output, error);
  if (error || size == 0) {
    const auto messages = condensed(errors.get());
    throw Error(fmt::format("cannot write '{}': gnuplot wrote no image{}{}", shown.string(),
                            messages.empty() ? "" : ": ", messages));
  }
}

}  // namespace

//! Renders script(temporary) into `png` (an image file of the format). A link is followed and
//! its target replaced atomically; a device or FIFO is written through
//! (hyst/io/output_paths.hpp).
void detail::write_image(const std::function<std::string(const fs::path& output)>& script,
                         const fs::path& png, ImageFormat format) {
  const io::OutputTarget target = io::resolve_output(png);
  if (target.kind == io::OutputKind::file) io::create_output_folder(target.path.parent_path());

  // The temporary image lies beside its target (in a staging folder when the target is one); for
  // a device or FIFO, whose folder may not take files (/dev), in the temporary folder.
  const bool special = target.kind == io::OutputKind::special;
  const fs::path temporary = temporary_path_for(
      special ? fs::temp_directory_path() / target.path.filename() : target.path, format);
  RemoveOnExit remove_temporary(temporary);
  render(script(temporary), temporary, -1, png);

  if (special) {
    io::write_file_atomically(target.path, io::read_file(temporary));
    return;
  }
  std::error_code error;
  fs::rename(temporary, target.path, error);
  if (error) {
    throw Error(fmt::format("cannot write '{}': {} (renaming '{}' over it)", png.string(),
                            error.message(), temporary.string()));
  }
  remove_temporary.release();
}

void write_png(const Figure& figure, const fs::path& png) {
  validate(figure);
  detail::write_image(
      [&](const fs::path& output) { return script_for(figure, output, Format::png); }, png,
      Format::png);
}

void write_svg(const Figure& figure, const fs::path& svg) {
  validate(figure);
  detail::write_image(
      [&](const fs::path& output) { return script_for(figure, output, Format::svg); }, svg,
      Format::svg);
}

std::string svg_element(const Figure& figure) {
  validate(figure);
  // gnuplot writes to an anonymous file (no name, so nothing is left behind if we are killed).
  const std::unique_ptr<std::FILE, FileCloser> image(std::tmpfile());
  if (!image) throw Error(fmt::format("cannot render an SVG: {}", errno_message(errno)));
  ::fcntl(::fileno(image.get()), F_SETFD, FD_CLOEXEC);
  render(script_for(figure, {}, Format::svg), {}, ::fileno(image.get()), "(SVG element)");
  std::rewind(image.get());
  std::string text;
  char buffer[65536];
  std::size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, image.get())) > 0)
    text.append(buffer, count);
  if (std::ferror(image.get())) throw Error("cannot read the SVG gnuplot wrote");
  const auto start = text.find("<svg");
  if (start == std::string::npos) throw Error("gnuplot wrote no <svg> element");
  return text.substr(start);
}

}  // namespace hyst::plot
