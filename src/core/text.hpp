// Text helpers for messages that quote what a user gave.
#pragma once

#include <string>

namespace gbssn1d {

/// Non-printable bytes of a text as \xNN, for messages that quote user input.
std::string printable(const std::string& s);

} // namespace gbssn1d
