#include "analysis/stats/magnitude_estimation.hpp"

#include <cmath>
#include <limits>
#include <map>

namespace ms {

namespace {

struct Rating {
  std::size_t listener, a, b;  // a <= b
  double log_value;
};

}  // namespace

MagnitudeEstimation magnitude_estimation(const TidyCsv& t, const MagnitudeColumns& c, const MagnitudeOptions& o) {
  const std::size_t cs = t.column(c.subject), c1 = t.column(c.first), c2 = t.column(c.second), cr = t.column(c.rating);
  MagnitudeEstimation out;
  out.modulus = o.modulus.has_value();
  std::map<std::string, std::size_t> token_index, listener_index;
  auto label = [&](std::size_t r, std::size_t col) -> const std::string& {
    const std::string& v = t.cell(r, col);
    if (v.empty()) throw InputError(t.where(r, col), "column '" + t.header()[col] + "': empty value");
    return v;
  };
  std::vector<Rating> ratings;
  ratings.reserve(t.rows());
  double grand_log = 0;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const std::string& who = label(r, cs);
    auto [li, new_listener] = listener_index.try_emplace(who, out.listeners.size());
    if (new_listener) out.listeners.push_back(MagnitudeListener{who, 0, 1, 0, 0});
    std::size_t ab[2];
    for (int k = 0; k < 2; ++k) {
      const std::string& tok = label(r, k == 0 ? c1 : c2);
      auto [ti, new_token] = token_index.try_emplace(tok, out.labels.size());
      if (new_token) out.labels.push_back(tok);
      ab[k] = ti->second;
    }
    const double v = t.number(r, cr);
    if (!(v > 0))
      throw InputError(t.where(r, cr), "column '" + c.rating + "': magnitude estimates must be positive (got " +
                                           t.cell(r, cr) + "); they are ratios to the modulus");
    MagnitudeListener& l = out.listeners[li->second];
    l.ratings += 1;
    l.geometric_mean += std::log(v);  // sum of logs for now
    grand_log += std::log(v);
    ratings.push_back(Rating{li->second, std::min(ab[0], ab[1]), std::max(ab[0], ab[1]), std::log(v)});
  }
  const std::size_t n = out.labels.size();
  if (n < 3) throw InputError(SourceLocation{t.file(), 1, 1}, "need pairs over at least 3 tokens");
  out.grand_geometric_mean = std::exp(grand_log / double(ratings.size()));
  std::vector<double> log_factor(out.listeners.size(), 0.0);
  std::size_t ma = 0, mb = 0;
  if (o.modulus) {
    for (const std::string* m : {&o.modulus->first, &o.modulus->second})
      if (!token_index.count(*m))
        throw InputError(SourceLocation{t.file(), 1, 1}, "modulus token '" + *m + "' does not occur in columns '" +
                                                             c.first + "' / '" + c.second + "'");
    ma = token_index[o.modulus->first];
    mb = token_index[o.modulus->second];
    if (ma > mb) std::swap(ma, mb);
    if (ma == mb) throw InputError("the modulus pair must be two different tokens");
  }
  std::vector<double> mod_log(out.listeners.size(), 0.0);
  std::vector<int> mod_count(out.listeners.size(), 0);
  if (o.modulus)
    for (const Rating& r : ratings)
      if (r.a == ma && r.b == mb) {
        mod_log[r.listener] += r.log_value;
        mod_count[r.listener] += 1;
      }
  for (std::size_t l = 0; l < out.listeners.size(); ++l) {
    MagnitudeListener& L = out.listeners[l];
    const double log_g = L.geometric_mean / double(L.ratings);
    L.geometric_mean = std::exp(log_g);
    if (o.modulus) {
      if (mod_count[l] == 0)
        throw InputError(SourceLocation{t.file(), 1, int(cs) + 1},
                         "listener '" + L.subject + "' never rated the modulus pair (" + o.modulus->first + ", " +
                             o.modulus->second + ")");
      const double log_m = mod_log[l] / mod_count[l];
      L.modulus_rating = std::exp(log_m);
      log_factor[l] = std::log(o.modulus_value) - log_m;
    } else {
      L.modulus_rating = std::numeric_limits<double>::quiet_NaN();
      log_factor[l] = grand_log / double(ratings.size()) - log_g;
    }
    L.factor = std::exp(log_factor[l]);
  }
  // Per (pair, listener): mean log; then mean over listeners.
  std::map<std::pair<std::size_t, std::size_t>, std::map<std::size_t, std::pair<double, int>>> cells;
  for (const Rating& r : ratings) {
    auto& cell = cells[{r.a, r.b}][r.listener];
    cell.first += r.log_value + log_factor[r.listener];
    cell.second += 1;
  }
  auto pair_mean = [&](std::size_t a, std::size_t b) {
    const auto it = cells.find({a, b});
    if (it == cells.end()) return std::numeric_limits<double>::quiet_NaN();
    double s = 0;
    for (const auto& [listener, acc] : it->second) s += acc.first / acc.second;
    return std::exp(s / double(it->second.size()));
  };
  out.dissimilarity = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
  out.self_ratings.resize(n);
  for (std::size_t a = 0; a < n; ++a) {
    out.self_ratings[a] = pair_mean(a, a);
    for (std::size_t b = a + 1; b < n; ++b) {
      const double v = pair_mean(a, b);
      if (std::isnan(v))
        throw InputError(SourceLocation{t.file(), 1, 1}, "the pair (" + out.labels[a] + ", " + out.labels[b] +
                                                             ") was never rated; every pair of tokens is needed");
      out.dissimilarity(Eigen::Index(a), Eigen::Index(b)) = out.dissimilarity(Eigen::Index(b), Eigen::Index(a)) = v;
    }
  }
  return out;
}

}  // namespace ms
