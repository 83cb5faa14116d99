// Difference to the reference per token; see difference_curve.hpp.
#include "analysis/stats/difference_curve.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>

namespace ms {

namespace {

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(v);
}

}  // namespace

std::vector<DifferencePoint> difference_to_reference(const TidyCsv& t, const MagnitudeColumns& c,
                                                     const std::string& reference, double offset,
                                                     const std::string& x_column) {
  const std::size_t cs = t.column(c.subject), c1 = t.column(c.first), c2 = t.column(c.second), cr = t.column(c.rating);
  const bool with_x = !x_column.empty();
  const std::size_t cx = with_x ? t.column(x_column) : 0;
  std::vector<std::string> tokens;  // in order of first appearance
  // token -> listener -> (sum, count) of the ratings of (reference, token)
  std::map<std::string, std::map<std::string, std::pair<double, int>>> sums;
  std::map<std::string, std::string> x_of;
  std::map<std::string, std::size_t> x_row;
  bool reference_seen = false;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const std::string &a = t.cell(r, c1), &b = t.cell(r, c2);
    if (with_x && a == b) {
      const std::string& x = t.cell(r, cx);
      if (x.empty())
        throw InputError(t.where(r, cx), "column '" + x_column + "': empty on the identical pair of '" + a +
                                             "' (give the stimulus `factors: {" + x_column + ": ...}`)");
      if (const auto it = x_of.find(a); it != x_of.end() && it->second != x)
        throw InputError(t.where(r, cx), "column '" + x_column + "': '" + x + "' for '" + a + "' here but '" +
                                             it->second + "' on line " + std::to_string(t.where(x_row[a], cx).line));
      x_of[a] = x;
      x_row[a] = r;
    }
    if (a == reference || b == reference) reference_seen = true;
    if ((a == reference) == (b == reference)) continue;  // not a pair of the reference with another token
    const std::string& token = a == reference ? b : a;
    const double v = t.number(r, cr);
    if (!sums.count(token)) tokens.push_back(token);
    auto& [sum, n] = sums[token][t.cell(r, cs)];
    sum += v;
    ++n;
  }
  if (!reference_seen)
    throw InputError(SourceLocation{t.file(), 1, 1}, "no row rates the reference '" + reference + "' (columns '" +
                                                         c.first + "', '" + c.second + "')");
  std::vector<DifferencePoint> out;
  for (const std::string& token : tokens) {
    DifferencePoint p;
    p.token = token;
    if (with_x) {
      const auto it = x_of.find(token);
      if (it == x_of.end())
        throw InputError(SourceLocation{t.file(), 1, 1}, "token '" + token + "' is never rated against itself, so column '" +
                                                             x_column + "' does not say its value (rate identical pairs too)");
      p.x = it->second;
    }
    std::vector<double> means;
    for (const auto& [listener, s] : sums[token]) means.push_back(s.first / s.second + offset);
    p.listeners = means.size();
    double sum = 0;
    for (double m : means) sum += m;
    p.mean = sum / double(means.size());
    double ss = 0;
    for (double m : means) ss += (m - p.mean) * (m - p.mean);
    p.sd = means.size() > 1 ? std::sqrt(ss / double(means.size() - 1)) : std::numeric_limits<double>::quiet_NaN();
    out.push_back(p);
  }
  if (with_x && std::all_of(out.begin(), out.end(), [](const DifferencePoint& p) { return is_number(p.x); }))
    std::stable_sort(out.begin(), out.end(), [](const DifferencePoint& a, const DifferencePoint& b) {
      return std::strtod(a.x.c_str(), nullptr) < std::strtod(b.x.c_str(), nullptr);
    });
  return out;
}

}  // namespace ms
