// Name tables: the one list of names an enum is written with (in parameter sets, protocols and on the
// command line). Reading a name, writing a value and suggesting the nearest name for a misspelling all
// go through the enum's table, so a name added to the table is read, written and suggested at once.
#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ms {

template <class Enum>
struct EnumName {
  Enum value;
  std::string_view name;
};

template <class Enum, std::size_t N>
using NameTable = std::array<EnumName<Enum>, N>;

template <class Enum, std::size_t N>
constexpr std::optional<Enum> find_enum(const NameTable<Enum, N>& table, std::string_view name) {
  for (const auto& entry : table)
    if (entry.name == name) return entry.value;
  return std::nullopt;
}

template <class Enum, std::size_t N>
constexpr std::string_view enum_name(const NameTable<Enum, N>& table, Enum value) {
  for (const auto& entry : table)
    if (entry.value == value) return entry.name;
  return "?";
}

template <class Enum, std::size_t N>
std::vector<std::string> enum_names(const NameTable<Enum, N>& table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.emplace_back(entry.name);
  return names;
}

// "unknown WHAT 'NAME' (expected a, b or c)", plus "; did you mean 'x'?" when one name is close.
std::string unknown_name_problem(const std::string& what, const std::string& name,
                                 const std::vector<std::string>& names);

template <class Enum, std::size_t N>
std::string unknown_name_problem(const std::string& what, const std::string& name, const NameTable<Enum, N>& table) {
  return unknown_name_problem(what, name, enum_names(table));
}

}  // namespace ms
