#include "synthesis/name_table.hpp"

#include "synthesis/yaml_reader.hpp"

namespace ms {

std::string unknown_name_problem(const std::string& what, const std::string& name,
                                 const std::vector<std::string>& names) {
  std::string expected;
  for (std::size_t i = 0; i < names.size(); ++i)
    expected += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  const std::string near = nearest_key(name, names);
  return "unknown " + what + " '" + name + "' (expected " + expected +
         (near.empty() ? "" : "; did you mean '" + near + "'?") + ")";
}

}  // namespace ms
