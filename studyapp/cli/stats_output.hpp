// What the `modalstudy` subcommands share to read option values and print results: numbers as
// printf formats them ("NA" when not finite), p as tables print it, JSON that writes null for a
// missing or non-finite number, notices on stderr, and a statistic's domain_error as one located line.
#pragma once
#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "synthesis/input_error.hpp"

namespace ms::cli {

// An option value that must be a finite number; InputError naming the option otherwise (exit 2).
double parse_number(const std::string& text, const std::string& option);

// `v` through printf format `f` (one double conversion, e.g. "%.4g"); "NA" when v is not finite.
std::string fmt(const char* f, double v);
// %.*g with `digits` significant digits.
std::string format_g(double v, int digits);

// p as published tables print it: "< .001" below 0.001, else three significant digits.
std::string fmt_p(double p);

// The number, or null when it is not finite (JSON has no NaN or infinity) or absent.
nlohmann::json num_json(double v);
nlohmann::json opt_json(const std::optional<double>& v);
nlohmann::json matrix_json(const Eigen::MatrixXd& m);

// "a,b" "c" -> {a, b, c}: repeatable options that also take comma-separated lists.
std::vector<std::string> split_commas(const std::vector<std::string>& args);

// One "notice: FILE: ..." line on stderr per notice.
void print_notices(const std::vector<std::string>& notices, const std::string& file);

// A statistic the data do not define (std::domain_error from the library) as one line naming the file.
template <class F>
auto located(const std::string& file, const std::string& what, F&& compute) {
  try {
    return compute();
  } catch (const std::domain_error& e) {
    throw InputError(SourceLocation{file, 0, 0}, what + ": " + e.what());
  }
}

}  // namespace ms::cli
