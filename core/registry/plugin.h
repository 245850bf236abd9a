#pragma once

#include <string>
#include <utility>
#include <vector>

namespace caustica {

// Base of every object a scene file can name with type="...".
class Plugin {
 public:
  virtual ~Plugin() = default;

  // The plugin's name and the effective value of each scalar parameter it
  // declares, in declaration order, as the registry recorded them when it
  // made the plugin (Properties::effective_parameters()).
  const std::string& plugin_name() const { return name_; }
  const std::vector<std::pair<std::string, std::string>>& parameters() const { return parameters_; }
  void set_parameters(std::string name, std::vector<std::pair<std::string, std::string>> parameters) {
    name_ = std::move(name);
    parameters_ = std::move(parameters);
  }
  // "NAME p=v q=w ...": the metadata string, derived from the declarations;
  // `except` leaves one parameter out.
  std::string describe_parameters(const std::string& except = "") const {
    std::string s = name_;
    for (const auto& [param, value] : parameters_)
      if (param != except) s += " " + param + "=" + value;
    return s;
  }

 private:
  std::string name_;
  std::vector<std::pair<std::string, std::string>> parameters_;
};

}  // namespace caustica
