// The subcommands' shared number formatting, JSON helpers and notices (stats_output.hpp).
#include "studyapp/cli/stats_output.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace ms::cli {

double parse_number(const std::string& text, const std::string& option) {
  double v = 0;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v))
    throw InputError(option + ": expected a finite number, got '" + text + "'");
  return v;
}

std::string fmt(const char* f, double v) {
  if (!std::isfinite(v)) return "NA";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string format_g(double v, int digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string fmt_p(double p) {
  if (!std::isfinite(p)) return "NA";
  if (p < 0.001) return "< .001";
  return fmt("%.3g", p);
}

nlohmann::json num_json(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json opt_json(const std::optional<double>& v) { return v ? num_json(*v) : nlohmann::json(nullptr); }

nlohmann::json matrix_json(const Eigen::MatrixXd& m) {
  nlohmann::json j = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index k = 0; k < m.cols(); ++k) row.push_back(m(i, k));
    j.push_back(row);
  }
  return j;
}

std::vector<std::string> split_commas(const std::vector<std::string>& args) {
  std::vector<std::string> out;
  for (const auto& a : args) {
    std::size_t start = 0;
    for (;;) {
      const auto comma = a.find(',', start);
      const std::string part = a.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      if (!part.empty()) out.push_back(part);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return out;
}

void print_notices(const std::vector<std::string>& notices, const std::string& file) {
  for (const auto& n : notices) std::cerr << "notice: " << file << ": " << n << "\n";
}

}  // namespace ms::cli
