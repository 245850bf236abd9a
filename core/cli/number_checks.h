#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace caustica {

// Command-line numbers that must be finite (nan and inf parse as doubles).
CLI::Validator finite_number();
// Finite and above zero.
CLI::Validator finite_positive();
// Finite and not negative.
CLI::Validator finite_non_negative();
// A whole number from 0 to `max`, written in decimal digits alone: a sign
// would make the unsigned parse wrap (-1 becoming 2^64 - 1).
CLI::Validator whole_number_up_to(uint64_t max, const std::string& max_text);

}  // namespace caustica
