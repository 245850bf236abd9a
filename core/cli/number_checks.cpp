#include "core/cli/number_checks.h"

#include <cmath>
#include <functional>
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

CLI::Validator finite_non_negative() {
  return number_check("a finite number of at least zero", [](double v) { return std::isfinite(v) && v >= 0; });
}

}  // namespace caustica
