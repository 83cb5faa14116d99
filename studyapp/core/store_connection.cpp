// SqlValue's conversions; see store_connection.hpp.
#include "studyapp/core/store_connection.hpp"

#include <charconv>
#include <stdexcept>

namespace ms {

namespace {

template <typename T>
T parse_number(const std::string& text) {
  T out{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  if (ec != std::errc{} || end != text.data() + text.size())
    throw std::runtime_error("results store: '" + text + "' is not a number");
  return out;
}

}  // namespace

std::int64_t SqlValue::int64() const {
  if (const auto* i = std::get_if<std::int64_t>(&v_)) return *i;
  if (const auto* d = std::get_if<double>(&v_)) return static_cast<std::int64_t>(*d);
  if (const auto* s = std::get_if<std::string>(&v_)) return parse_number<std::int64_t>(*s);
  return 0;
}

double SqlValue::real() const {
  if (const auto* d = std::get_if<double>(&v_)) return *d;
  if (const auto* i = std::get_if<std::int64_t>(&v_)) return static_cast<double>(*i);
  if (const auto* s = std::get_if<std::string>(&v_)) return parse_number<double>(*s);
  return 0.0;
}

std::string SqlValue::text() const {
  if (const auto* s = std::get_if<std::string>(&v_)) return *s;
  if (const auto* i = std::get_if<std::int64_t>(&v_)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&v_)) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, *d);  // shortest exact form
    return std::string(buf, end);
  }
  return {};
}

}  // namespace ms
