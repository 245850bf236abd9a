#pragma once

#include <CLI/CLI.hpp>

namespace caustica {

// Command-line numbers that must be finite (nan and inf parse as doubles).
CLI::Validator finite_number();
// Finite and above zero.
CLI::Validator finite_positive();
// Finite and not negative.
CLI::Validator finite_non_negative();

}  // namespace caustica
