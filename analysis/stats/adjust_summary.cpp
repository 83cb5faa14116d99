#include "analysis/stats/adjust_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace ms {

namespace {

// One answer: its time, plays and the value chosen per key (the rows it came from, for messages).
struct Answer {
  std::string group, object;
  double time_s = 0, plays = 0;
  std::size_t first_row = 0;
  std::vector<std::pair<std::string, double>> values;
};

template <class T>
std::size_t index_of(std::vector<T>& list, const T& item) {
  const auto it = std::find(list.begin(), list.end(), item);
  if (it != list.end()) return std::size_t(it - list.begin());
  list.push_back(item);
  return list.size() - 1;
}

double non_negative(const TidyCsv& t, std::size_t row, std::size_t col) {
  const double v = t.number(row, col);
  if (v < 0) throw InputError(t.where(row, col), "column '" + t.header()[col] + "': must not be negative, got " + t.cell(row, col));
  return v;
}

void mean_sd(const std::vector<double>& x, double& mean, double& sd) {
  mean = 0;
  for (double v : x) mean += v / double(x.size());
  double ss = 0;
  for (double v : x) ss += (v - mean) * (v - mean);
  sd = x.size() > 1 ? std::sqrt(ss / double(x.size() - 1)) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

AdjustSummary adjust_summary(const TidyCsv& t, const AdjustColumns& c) {
  const std::size_t object = t.column(c.object), key = t.column(c.key), value = t.column(c.value),
                    plays = t.column(c.plays), rt = t.column(c.rt_ms);
  const std::optional<std::size_t> group = c.group.empty() ? std::nullopt : std::optional(t.column(c.group));
  const std::optional<std::size_t> truth = c.truth.empty() ? std::nullopt : std::optional(t.column(c.truth));
  std::vector<std::size_t> answer_cols;
  for (const std::string& name : c.answer) answer_cols.push_back(t.column(name));
  if (t.rows() == 0) throw InputError(SourceLocation{t.file(), 0, 0}, "no data rows");

  std::vector<std::string> answer_ids;
  std::vector<Answer> answers;
  // (group, object, key) -> the stated truth and the row that stated it first
  std::map<std::tuple<std::string, std::string, std::string>, std::pair<std::optional<double>, std::size_t>> truths;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    std::string id;
    for (std::size_t col : answer_cols) id += t.cell(r, col) + '\x1f';
    const std::size_t before = answer_ids.size(), i = index_of(answer_ids, id);
    const std::string g = group ? t.cell(r, *group) : "";
    const double time_s = non_negative(t, r, rt) / 1000.0, n_plays = non_negative(t, r, plays);
    if (i == before) {
      answers.push_back({g, t.cell(r, object), time_s, n_plays, r, {}});
    } else {
      const Answer& a = answers[i];
      if (time_s != a.time_s || n_plays != a.plays || g != a.group || t.cell(r, object) != a.object) {
        const std::size_t col = time_s != a.time_s ? rt : n_plays != a.plays ? plays : g != a.group ? *group : object;
        throw InputError(t.where(r, col), "column '" + t.header()[col] + "': differs from line " +
                                              std::to_string(t.where(a.first_row).line) +
                                              " of the same answer (one answer's rows share it)");
      }
    }
    Answer& a = answers[i];
    const std::string& k = t.cell(r, key);
    for (const auto& [seen, v] : a.values)
      if (seen == k) throw InputError(t.where(r, key), "key '" + k + "' appears twice in one answer");
    a.values.emplace_back(k, t.number(r, value));
    if (!truth) continue;
    const std::string& text = t.cell(r, *truth);
    const std::optional<double> stated = text.empty() || text == "NA" ? std::nullopt : std::optional(t.number(r, *truth));
    const auto [it, fresh] = truths.try_emplace({g, a.object, k}, stated, r);
    if (!fresh && it->second.first != stated)
      throw InputError(t.where(r, *truth), "column '" + c.truth + "': '" + text + "' differs from the truth of the same " +
                                               "object and key on line " + std::to_string(t.where(it->second.second).line));
  }

  AdjustSummary out;
  std::vector<std::pair<std::string, std::string>> cells;  // (group, object) in order of first appearance
  std::vector<std::string> groups;
  for (const Answer& a : answers) {
    index_of(cells, std::pair(a.group, a.object));
    index_of(groups, a.group);
  }
  std::stable_sort(cells.begin(), cells.end(), [&](const auto& x, const auto& y) {  // by group, in order within
    const auto gx = std::find(groups.begin(), groups.end(), x.first), gy = std::find(groups.begin(), groups.end(), y.first);
    return gx < gy;
  });
  for (const auto& [g, o] : cells) {
    AdjustObject ob{g, o, {}, {}, {}};
    std::vector<double> times, played;
    std::vector<std::string> keys;
    std::vector<std::vector<double>> chosen;
    for (const Answer& a : answers) {
      if (a.group != g || a.object != o) continue;
      times.push_back(a.time_s);
      played.push_back(a.plays);
      for (const auto& [k, v] : a.values) {
        const std::size_t before = keys.size(), i = index_of(keys, k);
        if (i == before) chosen.emplace_back();
        chosen[i].push_back(v);
      }
    }
    ob.time_s = box_summary(times);
    ob.plays = box_summary(played);
    for (std::size_t i = 0; i < keys.size(); ++i) {
      AdjustParameter p;
      p.key = keys[i];
      p.chosen = box_summary(chosen[i]);
      mean_sd(chosen[i], p.mean, p.sd);
      const auto found = truths.find({g, o, keys[i]});
      if (found != truths.end()) p.truth = found->second.first;
      if (p.truth && *p.truth > 0) {
        std::vector<double> ratio;
        for (double v : chosen[i]) {
          if (v > 0) ratio.push_back(std::log10(v / *p.truth));
          else ++p.not_positive;
        }
        if (!ratio.empty()) {
          p.log10_ratio = box_summary(ratio);
          double sd = 0, ss = 0;
          mean_sd(ratio, p.log10_ratio_mean, sd);
          for (double v : ratio) ss += v * v;
          p.log10_ratio_rms = std::sqrt(ss / double(ratio.size()));
        }
      }
      ob.parameters.push_back(std::move(p));
    }
    out.objects.push_back(std::move(ob));
  }
  for (const std::string& g : groups) {
    std::vector<double> times, played;
    for (const Answer& a : answers)
      if (a.group == g) times.push_back(a.time_s), played.push_back(a.plays);
    out.groups.push_back({g, box_summary(times), box_summary(played)});
  }
  return out;
}

}  // namespace ms
