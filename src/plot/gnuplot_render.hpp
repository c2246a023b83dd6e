#pragma once
// Internal to the plot layer: what gnuplot.cpp shares with the other gnuplot figures
// (heat_map.cpp), so that every image is validated, quoted and written the same way.

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace hyst::plot::detail {

enum class ImageFormat { png, svg };

//! A gnuplot single-quoted string ('' for ', control characters as spaces).
std::string gnuplot_string(std::string_view text);

//! Throws hyst::Error unless both sides are within 16..20000 pixels.
void check_size(int width, int height);

//! The terminal and output commands: pngcairo (else png) or svg, noenhanced, the given size; an
//! empty `output` sends the image to standard output.
std::string terminal_commands(int width, int height, ImageFormat format,
                              const std::filesystem::path& output);

//! Runs gnuplot on script(output) and replaces `target` atomically with the image (the target's
//! folder must exist). Errors as write_png() in gnuplot.hpp.
void write_image(const std::function<std::string(const std::filesystem::path& output)>& script,
                 const std::filesystem::path& target, ImageFormat format);

}  // namespace hyst::plot::detail
