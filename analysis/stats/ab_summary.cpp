// ab_summary: counts per design, then the tests and d' of signal_detection.hpp and binomial_test.hpp.
#include "analysis/stats/ab_summary.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/stats/row_groups.hpp"
#include "analysis/stats/signal_detection.hpp"

namespace ms {

namespace {

void summarise_forced(const AbTrials& t, AbTask task, const AbSummaryOptions& o, AbSummary& s) {
  for (bool c : t.correct) s.correct += c;
  const unsigned k = s.correct, n = unsigned(t.correct.size());
  s.above_chance = binomial_test(k, n, o.chance, Alternative::greater, o.conf_level);
  s.two_sided = binomial_test(k, n, o.chance, Alternative::two_sided, o.conf_level);
  s.pc = double(k) / n;
  s.rates_corrected = k == 0 || k == n;
  const double pc = corrected_rate(k, n);
  s.dprime = task == AbTask::two_afc ? dprime_2afc(pc) : dprime_abx(pc);
}

void summarise_detection(const AbTrials& t, AbTask task, AbSummary& s) {
  for (std::size_t i = 0; i < t.signal.size(); ++i) {
    (t.signal[i] ? s.signal_trials : s.noise_trials) += 1;
    (t.signal[i] ? s.hits : s.false_alarms) += t.said_yes[i];
  }
  s.hit_rate = s.hits / s.signal_trials;
  s.false_alarm_rate = s.false_alarms / s.noise_trials;
  s.rates_corrected = s.hits == 0 || s.hits == s.signal_trials || s.false_alarms == 0 ||
                      s.false_alarms == s.noise_trials;
  const double h = corrected_rate(s.hits, s.signal_trials), f = corrected_rate(s.false_alarms, s.noise_trials);
  if (task == AbTask::yes_no) {
    s.dprime = dprime_yes_no(h, f);
    s.criterion_c = -(normal_quantile(h) + normal_quantile(f)) / 2;
  } else {
    const SameDifferent sd = dprime_same_different(h, f);
    s.dprime = sd.dprime;
    s.criterion_k = sd.criterion_k;
  }
}

void summarise_preference(const AbTrials& t, const AbSummaryOptions& o, AbSummary& s) {
  if (!t.choice.empty()) {
    AbPreference p;
    for (const std::string& v : t.choice) {
      if (v == o.options.at(0)) ++p.first;
      else if (v == o.options.at(1)) ++p.second;
      else ++p.ties;
    }
    if (p.first + p.second > 0)
      p.test = binomial_test(p.first, p.first + p.second, 0.5, Alternative::two_sided, o.conf_level);
    s.preference = p;
  }
  if (t.score.empty()) return;
  AbScore sc;
  sc.n = t.score.size();
  for (double v : t.score) sc.mean += v / double(sc.n);
  double squares = 0;
  for (double v : t.score) squares += (v - sc.mean) * (v - sc.mean);
  sc.sd = sc.n > 1 ? std::sqrt(squares / double(sc.n - 1)) : std::numeric_limits<double>::quiet_NaN();
  if (sc.n >= 2) {
    try {
      sc.test = paired_t_test(t.score, std::vector<double>(sc.n, 0.0), o.conf_level);
    } catch (const std::domain_error&) {  // all equal: no t statistic, the mean and sd still stand
    }
  }
  s.score = sc;
}

bool parse_correct(const TidyCsv& table, std::size_t r, std::size_t c) {
  std::string v = table.cell(r, c);
  for (char& ch : v) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  if (v == "1" || v == "true" || v == "yes" || v == "correct") return true;
  if (v == "0" || v == "false" || v == "no" || v == "incorrect") return false;
  throw InputError(table.where(r, c), "column '" + table.header()[c] + "': expected 1/0, true/false, yes/no or "
                                      "correct/incorrect, got '" + table.cell(r, c) + "'");
}

}  // namespace

int favoured_side(const AbScore& score) {
  if (!score.test) return score.n >= 2 && score.sd == 0 ? (score.mean > 0) - (score.mean < 0) : 0;  // all equal
  if (score.test->ci_low > 0) return 1;
  if (score.test->ci_high < 0) return -1;
  return 0;
}

AbSummary ab_summary(const AbTrials& trials, AbTask task, const AbSummaryOptions& options) {
  AbSummary s;
  s.group = trials.group;
  s.n = trials.n;
  if (task == AbTask::two_afc || task == AbTask::abx) summarise_forced(trials, task, options, s);
  else if (task == AbTask::preference) summarise_preference(trials, options, s);
  else summarise_detection(trials, task, s);
  return s;
}

std::vector<AbTrials> ab_trials_from_table(const TidyCsv& table, AbTask task, const AbColumns& columns) {
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
  const bool forced = task == AbTask::two_afc || task == AbTask::abx;
  const bool detection = task == AbTask::yes_no || task == AbTask::same_different;
  const bool choice = task == AbTask::preference && !columns.choice.empty();
  const bool score = task == AbTask::preference && !columns.score.empty();
  // Columns resolved before grouping, so that a missing one is reported first.
  const std::size_t c_correct = forced ? table.column(columns.correct) : 0;
  const std::size_t c_stim = detection ? table.column(columns.stimulus) : 0;
  const std::size_t c_resp = detection ? table.column(columns.response) : 0;
  const std::size_t c_choice = choice ? table.column(columns.choice) : 0;
  const std::size_t c_score = score ? table.column(columns.score) : 0;
  const bool per_subject = score && !columns.subject.empty();
  const std::size_t c_subject = per_subject ? table.column(columns.subject) : 0;
  std::vector<AbTrials> out;
  for (const auto& [name, rows] : group_rows(table, columns.by)) {
    AbTrials t;
    t.group = name;
    t.n = rows.size();
    for (std::size_t r : rows) {
      if (forced) t.correct.push_back(parse_correct(table, r, c_correct));
      if (detection) {
        t.signal.push_back(table.cell(r, c_stim) == columns.target);
        t.said_yes.push_back(table.cell(r, c_resp) == columns.yes);
      }
      if (choice) t.choice.push_back(table.cell(r, c_choice));
      if (score) t.score.push_back(table.number(r, c_score));
    }
    if (per_subject) {  // each subject's mean, subjects in order of first appearance
      std::vector<std::string> subjects;
      std::vector<double> sums, counts;
      for (std::size_t i = 0; i < rows.size(); ++i) {
        const std::string& who = table.cell(rows[i], c_subject);
        const auto at = std::size_t(std::find(subjects.begin(), subjects.end(), who) - subjects.begin());
        if (at == subjects.size()) {
          subjects.push_back(who);
          sums.push_back(0);
          counts.push_back(0);
        }
        sums[at] += t.score[i];
        counts[at] += 1;
      }
      t.averaged = subjects.size() < rows.size();
      t.score.clear();
      for (std::size_t k = 0; k < subjects.size(); ++k) t.score.push_back(sums[k] / counts[k]);
    }
    if (detection) {
      std::size_t signal = 0;
      for (bool s : t.signal) signal += s;
      if (signal == 0 || signal == t.n)
        throw InputError(table.where(rows.front(), c_stim),
                         "group '" + name + "' needs both '" + columns.target + "' trials and others in column '" +
                             table.header()[c_stim] + "'");
    }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace ms
