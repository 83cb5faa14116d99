// Hidden-effect cases for the audit tests: which effects a seed hides, with what strength, and the
// bookkeeping of what the audit named (confusion matrix, detection rates, gap shrink).
//  - tuning: seeds 1000-1059 and 1100-1179, strengths on the grid {0.1, 0.3, 0.5, 0.7, 0.9}; the
//    detector thresholds in analysis/audit/effect_*.cpp were chosen on these (DISABLED_AuditTuning
//    prints every statistic);
//  - test:   seeds 13000-13239, strengths drawn uniformly from (0, 1) off that grid (disjoint);
//    14000-14239 checked the path through the strikes once (AUDIT_HELDOUT_FIRST) and is spent too.
//    Earlier held-out ranges (5000-5119, 7000-7159, 8000-8159, 9000-9159, 10000-10239, 11000-11239,
//    12000-12239) are not reused.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "analysis/audit/audit.hpp"
#include "analysis/audit/hidden_effect_generator.hpp"

namespace ms::test {

// A seed range or count from the environment, or the default.
inline std::size_t env_or(const char* name, std::size_t fallback) {
  const char* v = std::getenv(name);
  return v ? std::stoul(v) : fallback;
}

// A comma-separated list from the environment (empty when unset).
inline std::vector<std::string> env_list(const char* name) {
  std::vector<std::string> out;
  const char* v = std::getenv(name);
  for (std::string rest = v ? v : ""; !rest.empty();) {
    const std::size_t comma = rest.find(',');
    out.push_back(rest.substr(0, comma));
    rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
  }
  return out;
}

// A case's effects and strengths from the environment (<prefix>_EFFECTS=a,b <prefix>_STRENGTHS=u,v;
// a strength not given is 0.5).
inline void env_case(const std::string& prefix, std::vector<std::string>& effects, std::vector<double>& strengths) {
  effects = env_list((prefix + "_EFFECTS").c_str());
  strengths.clear();
  for (const std::string& u : env_list((prefix + "_STRENGTHS").c_str())) strengths.push_back(std::stod(u));
  strengths.resize(effects.size(), 0.5);
}

struct CasePlan {
  std::uint64_t seed = 0;
  std::vector<std::string> effects;
  std::vector<double> strengths;
};

// Effects the runs hide: all the generator can hide.
inline std::vector<std::string> planned_effects() { return audit::hideable_effects(); }

// Case i of a run over the effects `all`: every (effects + 3) cases, 2 clean, one with each effect,
// 1 with a random pair.
inline CasePlan plan_case(std::uint64_t seed, std::size_t i, bool grid_strengths, const std::vector<std::string>& all) {
  std::mt19937_64 rng(seed * 7919u + 17u);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  auto strength = [&] {
    if (grid_strengths) return 0.1 + 0.2 * double(rng() % 5);
    double u = U(rng);
    for (double g : {0.1, 0.3, 0.5, 0.7, 0.9})
      if (std::abs(u - g) < 1e-9) u += 0.01;  // keep off the tuning grid
    return u;
  };
  CasePlan p;
  p.seed = seed;
  const std::size_t k = i % (all.size() + 3);
  if (k >= 2 && k < all.size() + 2) {
    p.effects = {all[k - 2]};
    p.strengths = {strength()};
  } else if (k == all.size() + 2) {
    const std::size_t a = rng() % all.size();
    std::size_t b = rng() % (all.size() - 1);
    if (b >= a) ++b;
    p.effects = {all[a], all[b]};
    p.strengths = {strength(), strength()};
  }
  return p;
}

// ... over the effects the first generator hides.
inline CasePlan plan_case(std::uint64_t seed, std::size_t i, bool grid_strengths) {
  return plan_case(seed, i, grid_strengths, planned_effects());
}

struct Tally {
  std::vector<std::string> labels;  // effects + "none"
  std::map<std::string, std::map<std::string, int>> confusion;  // hidden -> named -> count
  std::map<std::string, int> hidden, hit;
  int clean = 0, clean_quiet = 0;
  int with_effect = 0, shrunk = 0;
  int halved_above_floor = 0;  // the held-out gap above the repeatability floor at least halves
  // The same without the cases at the floor: nothing named, and the strikes share nothing resolved beyond
  // the model (repeatability_floor.hpp's SharedResidual). For an effect that varies from strike to strike
  // (hit points, hand damping, contacts) that does not make it invisible, only not shared.
  std::map<std::string, int> hidden_resolved, hit_resolved;
  // Missed while the effects named beside it already close kClosedShare of the held-out gap above the
  // floor: no gap criterion can then name it (what it would explain lies within what repetition allows).
  static constexpr double kClosedShare = 0.95;
  std::map<std::string, int> missed_closed;
  int with_effect_resolved = 0, halved_resolved = 0;
  std::vector<double> shrink, floor_db;
  // The confusion matrix's rows (hidden) and columns (named), "none" last in each; empty: the first
  // generator's effects for both.
  std::vector<std::string> rows, columns;

  void add(const CasePlan& plan, const audit::AuditResult& r) {
    std::vector<std::string> named;
    for (const auto& n : r.named) named.push_back(n.effect);
    const std::vector<std::string> hidden_list = plan.effects.empty() ? std::vector<std::string>{"none"} : plan.effects;
    const std::vector<std::string> named_list = named.empty() ? std::vector<std::string>{"none"} : named;
    for (const auto& h : hidden_list)
      for (const auto& n : named_list) confusion[h][n] += 1;
    if (plan.effects.empty()) {
      ++clean;
      clean_quiet += named.empty();
      return;
    }
    const bool resolved = !r.named.empty() || r.left_shared.resolved();
    for (const auto& h : plan.effects) {
      ++hidden[h];
      hidden_resolved[h] += resolved;
      for (const auto& n : named) {
        hit[h] += n == h;
        hit_resolved[h] += resolved && n == h;
      }
      missed_closed[h] += std::find(named.begin(), named.end(), h) == named.end() && r.share_above_floor >= kClosedShare;
    }
    ++with_effect;
    with_effect_resolved += resolved;
    floor_db.push_back(r.floor_db);
    halved_above_floor += r.share_above_floor >= 0.5;
    halved_resolved += resolved && r.share_above_floor >= 0.5;
    const double s = r.gap_before_db > 0 ? 1.0 - r.gap_after_db / r.gap_before_db : 0.0;
    shrink.push_back(s);
    shrunk += s >= 0.5;
  }

  void print() const {
    std::vector<std::string> cols = audit::hideable_effects();  // columns: everything the audit can name
    cols.push_back("none");
    if (!columns.empty()) cols = columns;
    const std::vector<std::string> row_labels = rows.empty() ? cols : rows;
    std::printf("confusion (rows: hidden, columns: named; a case with two effects counts in both rows)\n%-17s", "");
    for (const auto& c : cols) std::printf("%17s", c.c_str());
    std::printf("\n");
    for (const auto& r : row_labels) {
      std::printf("%-17s", r.c_str());
      for (const auto& c : cols) {
        const auto it = confusion.find(r);
        int v = 0;
        if (it != confusion.end() && it->second.count(c)) v = it->second.at(c);
        std::printf("%17d", v);
      }
      std::printf("\n");
    }
    const auto count = [](const std::map<std::string, int>& m, const std::string& e) { return m.count(e) ? m.at(e) : 0; };
    for (const auto& [e, n] : hidden)
      std::printf("%-17s named in %d of %d cases where hidden (%.0f %%); in %d of %d not at the floor; of the %d "
                  "missed, %d with >= %.0f %% of the held-out gap above the floor closed by the others\n",
                  e.c_str(), count(hit, e), n, 100.0 * count(hit, e) / n, count(hit_resolved, e), count(hidden_resolved, e),
                  n - count(hit, e), count(missed_closed, e), 100.0 * kClosedShare);
    std::printf("clean: nothing named in %d of %d (%.0f %%)\n", clean_quiet, clean, clean ? 100.0 * clean_quiet / clean : 0.0);
    std::printf("gap shrinks by >= 50 %% in %d of %d cases with an effect (%.0f %%)\n", shrunk, with_effect,
                with_effect ? 100.0 * shrunk / with_effect : 0.0);
    std::vector<double> f = floor_db;
    std::sort(f.begin(), f.end());
    std::printf("held-out gap above the repeatability floor halves in %d of %d cases with an effect (%.0f %%); "
                "floor median %.3f dB, max %.3f dB\n",
                halved_above_floor, with_effect, with_effect ? 100.0 * halved_above_floor / with_effect : 0.0,
                f.empty() ? 0.0 : f[f.size() / 2], f.empty() ? 0.0 : f.back());
    std::printf("... in %d of %d cases not at the floor (at it: nothing named, and nothing shared beyond the model "
                "resolved)\n",
                halved_resolved, with_effect_resolved);
  }
};

}  // namespace ms::test
