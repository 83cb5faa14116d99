// Distinguished tokens per listener and sequence; see distinguished_tokens.hpp.
#include "analysis/stats/distinguished_tokens.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/stats/quantile.hpp"
#include "analysis/stats/row_groups.hpp"
#include "analysis/stats/token_series.hpp"

namespace ms {

namespace {

// A token's number of modes: a whole number >= 1.
int modes_at(const TidyCsv& t, std::size_t row, std::size_t col, const std::string& name) {
  const double v = t.number(row, col);
  if (v < 1 || v != std::floor(v) || v > 1e6)
    throw InputError(t.where(row, col), "column '" + name + "': a number of modes is a whole number from 1, got '" +
                                            t.cell(row, col) + "'");
  return int(v);
}

std::string joined(const TidyCsv& t, std::size_t row, const std::vector<std::size_t>& cols) {
  std::string out;
  for (std::size_t c : cols) out += (out.empty() ? "" : "/") + t.cell(row, c);
  return out;
}

}  // namespace

std::vector<TokenCount> token_counts_from_table(const TidyCsv& table, const TokenColumns& columns) {
  const std::size_t cr = table.column(columns.reference), cc = table.column(columns.comparison),
                    cd = table.column(columns.different), cp = table.column(columns.participant);
  std::vector<std::size_t> condition_cols;
  for (const auto& c : columns.condition) condition_cols.push_back(table.column(c));
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
  std::vector<TokenCount> out;
  for (const auto& [name, rows] : group_rows(table, columns.series)) {
    const int from = modes_at(table, rows.front(), cr, columns.reference);
    const int to = from - int(rows.size());
    if (to < 1)
      throw InputError(table.where(rows.back(), cc), "series '" + name + "' has " + std::to_string(rows.size()) +
                                                         " comparisons, more than its first reference's " +
                                                         std::to_string(from) + " modes allow");
    TokenSeries series(from, to);
    const std::string condition = joined(table, rows.front(), condition_cols);
    for (std::size_t r : rows) {
      if (const int c = modes_at(table, r, cc, columns.comparison); c != series.comparison())
        throw InputError(table.where(r, cc), "column '" + columns.comparison + "': series '" + name + "' compares " +
                                                 std::to_string(series.comparison()) + " modes here (one below the " +
                                                 "previous comparison), not " + table.cell(r, cc));
      if (const int ref = modes_at(table, r, cr, columns.reference); ref != series.reference())
        throw InputError(table.where(r, cr), "column '" + columns.reference + "': series '" + name +
                                                 "': the answers so far make " + std::to_string(series.reference()) +
                                                 " modes the reference here, not " + table.cell(r, cr));
      const std::string& d = table.cell(r, cd);
      if (d != "0" && d != "1")
        throw InputError(table.where(r, cd), "column '" + columns.different + "': expected 1 (different) or 0 (same), got '" + d + "'");
      if (joined(table, r, condition_cols) != condition)
        throw InputError(table.where(r, condition_cols.empty() ? 0 : condition_cols.front()),
                         "series '" + name + "' changes condition from '" + condition + "' to '" +
                             joined(table, r, condition_cols) + "' (add the condition columns to the series columns)");
      series.record(d == "1");
    }
    out.push_back({name, table.cell(rows.front(), cp), condition, int(series.distinguished().size()), series.tokens()});
  }
  return out;
}

TokensTable tokens_table(const std::vector<TokenCount>& counts) {
  TokensTable t;
  const auto index_of = [](std::vector<std::string>& names, const std::string& n) {
    const auto it = std::find(names.begin(), names.end(), n);
    if (it != names.end()) return std::size_t(it - names.begin());
    names.push_back(n);
    return names.size() - 1;
  };
  for (const TokenCount& c : counts) {
    index_of(t.participants, c.participant);
    index_of(t.conditions, c.condition);
  }
  const std::size_t np = t.participants.size(), nc = t.conditions.size();
  std::vector<std::vector<double>> sum(np, std::vector<double>(nc, 0.0)), share_sum = sum;
  t.series.assign(np, std::vector<std::size_t>(nc, 0));
  t.summary.resize(nc);
  for (std::size_t c = 0; c < nc; ++c) {
    t.summary[c].name = t.conditions[c];
    t.summary[c].tokens_min = std::numeric_limits<int>::max();
  }
  for (const TokenCount& c : counts) {
    const std::size_t p = index_of(t.participants, c.participant), k = index_of(t.conditions, c.condition);
    sum[p][k] += c.distinguished;
    share_sum[p][k] += double(c.distinguished) / double(c.tokens);
    ++t.series[p][k];
    t.summary[k].tokens_min = std::min(t.summary[k].tokens_min, c.tokens);
    t.summary[k].tokens_max = std::max(t.summary[k].tokens_max, c.tokens);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  t.count.assign(np, std::vector<double>(nc, nan));
  t.share = t.count;
  for (std::size_t k = 0; k < nc; ++k) {
    std::vector<double> counts_k, shares_k;
    for (std::size_t p = 0; p < np; ++p) {
      if (t.series[p][k] == 0) continue;
      t.count[p][k] = sum[p][k] / double(t.series[p][k]);
      t.share[p][k] = share_sum[p][k] / double(t.series[p][k]);
      counts_k.push_back(t.count[p][k]);
      shares_k.push_back(t.share[p][k]);
    }
    TokensCondition& s = t.summary[k];
    s.participants = counts_k.size();
    s.median = median(counts_k);
    s.min = *std::min_element(counts_k.begin(), counts_k.end());
    s.max = *std::max_element(counts_k.begin(), counts_k.end());
    s.median_share = median(shares_k);
  }
  return t;
}

}  // namespace ms
