// BS.1116 summary; see bs1116.hpp.
#include "analysis/stats/bs1116.hpp"

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "synthesis/input_error.hpp"

namespace ms {

namespace {

Bs1116Assessor screen(const std::string& subject, const std::vector<double>& d) {
  Bs1116Assessor a;
  a.subject = subject;
  a.trials = d.size();
  for (double x : d) a.positive += x > 0;
  const MushraStat s = describe(subject, d, 0.95);
  a.mean = s.mean;
  if (d.size() < 2) return a;
  const double se = s.sd / std::sqrt(double(d.size()));
  if (!(se > 0)) return a;  // every grade equal: t is undefined
  a.t = a.mean / se;
  a.p_less = boost::math::cdf(boost::math::students_t(double(d.size() - 1)), *a.t);
  return a;
}

}  // namespace

Bs1116Result bs1116_analyse(const std::vector<Bs1116Grade>& grades, double conf_level) {
  Bs1116Result out;
  std::vector<std::string> subjects, conditions;
  std::map<std::string, std::vector<double>> by_subject;
  std::map<std::pair<std::string, std::string>, std::vector<double>> cell;  // (condition, subject)
  for (const Bs1116Grade& g : grades) {
    if (!by_subject.count(g.subject)) subjects.push_back(g.subject);
    by_subject[g.subject].push_back(g.diffgrade);
    if (std::find(conditions.begin(), conditions.end(), g.condition) == conditions.end())
      conditions.push_back(g.condition);
    cell[{g.condition, g.subject}].push_back(g.diffgrade);
  }
  for (const std::string& s : subjects) out.assessors.push_back(screen(s, by_subject[s]));
  for (const std::string& c : conditions) {
    std::vector<double> means;  // one per assessor who graded the condition
    for (const std::string& s : subjects) {
      const auto it = cell.find({c, s});
      if (it == cell.end()) continue;
      means.push_back(describe(s, it->second, conf_level).mean);
      out.averaged += it->second.size() > 1;
    }
    MushraStat stat = describe(c, means, conf_level);
    stat.ci_past_scale = stat.ci_low && (*stat.ci_low < -4.0 || *stat.ci_high > 4.0);  // the −4..4 scale
    out.conditions.push_back(stat);
  }
  return out;
}

std::vector<Bs1116Grade> bs1116_from_table(const TidyCsv& table) {
  const bool tidy = table.has_column("diffgrade");
  const std::size_t cs = table.first_column({"participant", "session_uuid"});
  const std::size_t cc = table.first_column({"condition", "rating_non_reference"});
  const std::size_t cd = table.column(tidy ? "diffgrade" : "rating_non_reference_score");
  const std::size_t cr = tidy ? cd : table.column("rating_reference_score");
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
  std::vector<Bs1116Grade> out;
  for (std::size_t r = 0; r < table.rows(); ++r) {
    for (std::size_t c : {cs, cc})
      if (table.cell(r, c).empty()) throw InputError(table.where(r, c), "column '" + table.header()[c] + "': empty");
    const double d = tidy ? table.number(r, cd) : table.number(r, cd) - table.number(r, cr);
    if (!(d >= -4.0 && d <= 4.0))
      throw InputError(table.where(r, cd), "column '" + table.header()[cd] + "': difference grade " +
                                               std::to_string(d) + " outside -4..4 (grades are 1.0-5.0)");
    out.push_back({table.cell(r, cs), table.cell(r, cc), d});
  }
  return out;
}

}  // namespace ms
