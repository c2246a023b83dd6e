#pragma once
//! \file
//! Text for XML and HTML documents hyst writes (an FMU's model description, the comparison page).

#include <string>
#include <string_view>

namespace hyst::io {

//! `text` with the five characters XML reserves (& < > " ') written as entities, so that it can
//! stand in element content and in attribute values of either quote.
std::string xml_escaped(std::string_view text);

}  // namespace hyst::io
