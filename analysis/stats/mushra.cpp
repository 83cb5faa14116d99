#include "analysis/stats/mushra.hpp"

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>

namespace ms {

MushraStat describe(const std::string& name, const std::vector<double>& values, double conf_level) {
  MushraStat s;
  s.condition = name;
  s.n = values.size();
  if (s.n == 0) return s;
  for (double v : values) s.mean += v;
  s.mean /= double(s.n);
  if (s.n < 2) return s;
  double ss = 0;
  for (double v : values) ss += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(ss / double(s.n - 1));
  const double t = boost::math::quantile(boost::math::students_t(double(s.n - 1)), 0.5 + conf_level / 2);
  const double half = t * s.sd / std::sqrt(double(s.n));
  s.ci_low = s.mean - half;
  s.ci_high = s.mean + half;
  s.ci_past_scale = *s.ci_low < 0.0 || *s.ci_high > 100.0;
  return s;
}

namespace {

// Index of a name in first-appearance order.
std::size_t intern(std::vector<std::string>& names, std::unordered_map<std::string, std::size_t>& index,
                   const std::string& name) {
  auto [it, added] = index.try_emplace(name, names.size());
  if (added) names.push_back(name);
  return it->second;
}

}  // namespace

MushraResult mushra_analyse(const std::vector<MushraRating>& ratings, const MushraOptions& options) {
  std::vector<std::string> subjects, items, conditions;
  std::unordered_map<std::string, std::size_t> si, ii, ci;
  // (subject, item, condition) -> (sum, count): one averaged rating per cell.
  std::map<std::tuple<std::size_t, std::size_t, std::size_t>, std::pair<double, int>> cell;
  for (const auto& r : ratings) {
    auto& c = cell[{intern(subjects, si, r.subject), intern(items, ii, r.item), intern(conditions, ci, r.condition)}];
    c.first += r.rating;
    c.second += 1;
  }
  MushraResult out;
  out.assessors.resize(subjects.size());
  for (std::size_t s = 0; s < subjects.size(); ++s) {
    out.assessors[s].subject = subjects[s];
    for (const auto& anchor : options.anchors) out.assessors[s].anchors.push_back(MushraAnchorCheck{anchor, 0, 0, false});
  }
  auto anchor_index = [&](const std::string& c) {
    return std::size_t(std::find(options.anchors.begin(), options.anchors.end(), c) - options.anchors.begin());
  };
  for (const auto& [key, v] : cell) {
    const auto [s, i, c] = key;
    out.averaged += v.second > 1;
    const double mean = v.first / v.second;
    MushraAssessor& a = out.assessors[s];
    if (conditions[c] == options.reference) {
      a.reference_items += 1;
      a.reference_below += mean < options.reference_min;
    } else if (const std::size_t k = anchor_index(conditions[c]); k < options.anchors.size()) {
      a.anchors[k].items += 1;
      a.anchors[k].above += mean > options.anchor_max;
    }
  }
  for (auto& a : out.assessors) {
    a.reference_fails = a.reference_items > 0 && double(a.reference_below) > options.max_fraction * double(a.reference_items);
    for (auto& k : a.anchors) {
      k.fails = k.items > 0 && double(k.above) > options.max_fraction * double(k.items);
      a.anchor_fails |= k.fails;
    }
    a.excluded = a.reference_fails || (options.screen_anchors && a.anchor_fails);
    out.included += !a.excluded;
  }
  std::vector<std::vector<double>> by_condition(conditions.size());
  std::vector<std::vector<std::vector<double>>> by_item(items.size(), std::vector<std::vector<double>>(conditions.size()));
  for (const auto& [key, v] : cell) {
    const auto [s, i, c] = key;
    if (out.assessors[s].excluded) continue;
    by_condition[c].push_back(v.first / v.second);
    by_item[i][c].push_back(v.first / v.second);
  }
  for (std::size_t c = 0; c < conditions.size(); ++c)
    out.conditions.push_back(describe(conditions[c], by_condition[c], options.conf_level));
  for (std::size_t i = 0; i < items.size(); ++i) {
    MushraItem it{items[i], {}};
    for (std::size_t c = 0; c < conditions.size(); ++c)
      it.conditions.push_back(describe(conditions[c], by_item[i][c], options.conf_level));
    out.items.push_back(std::move(it));
  }
  return out;
}

}  // namespace ms

namespace ms {

namespace {

// The first of `candidates` the table has, or the explicit choice when given.
std::size_t pick_column(const TidyCsv& table, const std::string& chosen, const std::vector<std::string>& candidates) {
  return chosen.empty() ? table.first_column(candidates) : table.column(chosen);
}

}  // namespace

MushraTable mushra_from_table(const TidyCsv& table, const MushraColumns& columns, const MushraOptions& options) {
  const std::size_t cs = pick_column(table, columns.subject, {"participant", "subject", "session_uuid"});
  const std::size_t ci = pick_column(table, columns.item, {"trial", "item", "trial_id"});
  const std::size_t cc = pick_column(table, columns.condition, {"condition", "rating_stimulus"});
  const std::size_t cr = pick_column(table, columns.rating, {"rating", "rating_score"});
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
  MushraTable out{{}, options};
  std::set<std::string> conditions;
  for (std::size_t r = 0; r < table.rows(); ++r) {
    const double v = table.number(r, cr);
    if (v < 0 || v > 100)
      throw InputError(table.where(r, cr), "column '" + table.header()[cr] + "': rating " + table.cell(r, cr) +
                                               " outside the MUSHRA scale 0-100");
    for (std::size_t c : {cs, ci, cc})
      if (table.cell(r, c).empty()) throw InputError(table.where(r, c), "column '" + table.header()[c] + "': empty");
    out.ratings.push_back(MushraRating{table.cell(r, cs), table.cell(r, ci), table.cell(r, cc), v});
    conditions.insert(table.cell(r, cc));
  }
  const SourceLocation header{table.file(), 1, 1};
  if (!conditions.count(options.reference))
    throw InputError(header, "no condition named '" + options.reference + "' in column '" + table.header()[cc] +
                                 "' (name the hidden reference with --reference)");
  if (options.anchors.empty()) {
    for (const auto& c : conditions)
      if (c.rfind("anchor", 0) == 0) out.options.anchors.push_back(c);
  } else {
    for (const auto& a : options.anchors)
      if (!conditions.count(a))
        throw InputError(header, "--anchor: no condition named '" + a + "' in column '" + table.header()[cc] + "'");
  }
  return out;
}

}  // namespace ms
