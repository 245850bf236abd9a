#include "core/cli/number_checks.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace caustica {

namespace {

CLI::Validator number_check(const std::string& description, std::function<bool(double)> accept) {
  return CLI::Validator(
      [description, accept](std::string& text) -> std::string {
        double value = 0;
        size_t used = 0;
        try {
          value = std::stod(text, &used);
        } catch (const std::exception&) {
          return "'" + text + "' is not a number";
        }
        if (used != text.size() || !accept(value)) return "'" + text + "' is not " + description;
        return {};
      },
      description);
}

}  // namespace

CLI::Validator finite_number() {
  return number_check("a finite number", [](double v) { return std::isfinite(v); });
}

CLI::Validator finite_positive() {
  return number_check("a finite number above zero", [](double v) { return std::isfinite(v) && v > 0; });
}

CLI::Validator whole_number_up_to(uint64_t max, const std::string& max_text) {
  const std::string description = "a whole number from 0 to " + max_text;
  return CLI::Validator(
      [description, max](std::string& text) -> std::string {
        const bool digits = !text.empty() && text.size() <= 20 &&
                            std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (!digits) return "'" + text + "' is not " + description;
        // 20 digits may pass 2^64: compare as text against the largest value first.
        const std::string largest = std::to_string(std::numeric_limits<uint64_t>::max());
        if (text.size() == largest.size() && text > largest) return "'" + text + "' is not " + description;
        if (std::stoull(text) > max) return "'" + text + "' is not " + description;
        return {};
      },
      description);
}

CLI::Validator finite_non_negative() {
  return number_check("a finite number of at least zero", [](double v) { return std::isfinite(v) && v >= 0; });
}

}  // namespace caustica
