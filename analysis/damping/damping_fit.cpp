// Damping-law estimators (LSQ, LB, EMG). All work on the scaled data of EmgProblem (x = lambda/max lambda,
// y = c/median c) so that every parameter is O(1); results are converted back to physical units.
#include "analysis/damping/damping_fit.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <stdexcept>

#include "analysis/damping/emg_likelihood.hpp"

namespace ms {

DampingEstimator parse_damping_estimator(const std::string& name) {
  if (name == "lsq") return DampingEstimator::lsq;
  if (name == "lb") return DampingEstimator::lb;
  if (name == "emg") return DampingEstimator::emg;
  throw std::invalid_argument("unknown estimator '" + name + "' (expected emg, lsq or lb)");
}

std::string to_string(DampingEstimator estimator) {
  switch (estimator) {
    case DampingEstimator::lsq: return "lsq";
    case DampingEstimator::lb: return "lb";
    case DampingEstimator::emg: return "emg";
  }
  return "?";
}

std::size_t damping_fit_param_count(DampingKind law, DampingEstimator estimator) {
  return std::size_t(law_param_count(law)) + (estimator == DampingEstimator::emg ? 2 : 0);
}

namespace {

struct Line {
  double intercept = 0.0, slope = 0.0;
  double objective = 0.0;  // LB: sum of vertical distances; LSQ: residual sum of squares
};

// Lower convex hull of (u, v) (order sorts by u, then v) and its edge above mean u: the LB line.
Line lower_bound_line(const std::vector<double>& u, const std::vector<double>& v,
                      const std::vector<std::size_t>& order, std::vector<std::size_t>& hull) {
  const double n = double(u.size());
  double mean_u = 0.0, sum_v = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    mean_u += u[i];
    sum_v += v[i];
  }
  mean_u /= n;
  hull.clear();
  for (std::size_t idx : order) {
    if (!hull.empty() && u[idx] == u[hull.back()]) continue;  // same abscissa: the lowest came first
    while (hull.size() >= 2) {
      const std::size_t o = hull[hull.size() - 2], a = hull.back();
      const double cross = (u[a] - u[o]) * (v[idx] - v[o]) - (v[a] - v[o]) * (u[idx] - u[o]);
      if (cross > 0) break;  // strict left turn: a stays on the lower hull
      hull.pop_back();
    }
    hull.push_back(idx);
  }
  Line line;
  if (hull.size() == 1) {  // all abscissae equal: the LP only fixes the level (slope 0 by convention)
    line.intercept = v[hull[0]];
  } else {
    std::size_t j = 0;
    while (j + 2 < hull.size() && u[hull[j + 1]] < mean_u) ++j;
    const std::size_t i0 = hull[j], i1 = hull[j + 1];
    line.slope = (v[i1] - v[i0]) / (u[i1] - u[i0]);
    line.intercept = v[i0] - line.slope * u[i0];
  }
  line.objective = sum_v - n * (line.intercept + line.slope * mean_u);
  return line;
}

// Ordinary least squares of v on u (with intercept, or through the origin).
Line least_squares_line(const std::vector<double>& u, const std::vector<double>& v, bool with_intercept) {
  const double n = double(u.size());
  Line line;
  if (!with_intercept) {
    double suv = 0, suu = 0, svv = 0;
    for (std::size_t i = 0; i < u.size(); ++i) {
      suv += u[i] * v[i];
      suu += u[i] * u[i];
      svv += v[i] * v[i];
    }
    line.slope = suu > 0 ? suv / suu : 0.0;
    line.objective = svv - line.slope * suv;
    return line;
  }
  double mu = 0, mv = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    mu += u[i];
    mv += v[i];
  }
  mu /= n;
  mv /= n;
  double suv = 0, suu = 0, svv = 0;  // centred, for accuracy
  for (std::size_t i = 0; i < u.size(); ++i) {
    suv += (u[i] - mu) * (v[i] - mv);
    suu += (u[i] - mu) * (u[i] - mu);
    svv += (v[i] - mv) * (v[i] - mv);
  }
  line.slope = suu > 0 ? suv / suu : 0.0;
  line.intercept = mv - line.slope * mu;
  line.objective = svv - line.slope * suv;
  return line;
}

// Minimise f over the exponent p in [0.1, 3]: grid (step 0.1), then golden section around the best
// grid point. Returns p; *evaluations counts calls of f.
double minimise_exponent(const std::function<double(double)>& f, int* evaluations) {
  double best_p = 1.0, best_f = f(1.0);
  int evals = 1;
  for (int g = 1; g <= 30; ++g) {
    const double p = 0.1 * g;
    const double v = f(p);
    ++evals;
    if (v < best_f) best_f = v, best_p = p;
  }
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = std::max(0.05, best_p - 0.1), hi = best_p + 0.1;
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  evals += 2;
  while (hi - lo > 1e-10) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = f(x2);
    }
    ++evals;
  }
  const double p = 0.5 * (lo + hi);
  if (evaluations) *evaluations += evals;
  return f(p) <= best_f ? p : best_p;
}

// Residual sum of squares of the scaled law theta (law part) and its Gauss-Newton polish: the 1-D
// profile search leaves alpha3 at ~sqrt(eps) (the RSS is flat at its minimum); a few Gauss-Newton
// steps on all law parameters reach the least-squares optimum to rounding. `*evaluations` counts steps.
double law_rss(const EmgProblem& pr, const EmgVector& theta);

void polish_least_squares(const EmgProblem& pr, EmgVector& theta, int* evaluations) {
  const int k = int(theta.size());
  double rss = law_rss(pr, theta);
  for (int it = 0; it < 30; ++it) {
    Eigen::MatrixXd JtJ = Eigen::MatrixXd::Zero(k, k);
    Eigen::VectorXd Jtr = Eigen::VectorXd::Zero(k);
    Eigen::VectorXd grad_m(k);
    for (std::size_t i = 0; i < pr.x.size(); ++i) {
      const double pw = std::exp(theta[k - 1] * pr.log_x[i]);
      const double b = theta[k - 2];
      const double m = (k == 3 ? theta[0] : 0.0) + b * pw;
      if (k == 3) grad_m[0] = 1.0;
      grad_m[k - 2] = pw;
      grad_m[k - 1] = b * pw * pr.log_x[i];
      JtJ.selfadjointView<Eigen::Lower>().rankUpdate(grad_m);
      Jtr += (pr.y[i] - m) * grad_m;
    }
    const Eigen::VectorXd step = JtJ.selfadjointView<Eigen::Lower>().ldlt().solve(Jtr);
    if (!step.allFinite()) break;
    double t = 1.0;
    bool improved = false;
    for (int ls = 0; ls < 30 && !improved; ++ls, t *= 0.5) {
      const EmgVector trial = theta + t * step;
      const double r = law_rss(pr, trial);
      if (r <= rss) {
        improved = r < rss;
        theta = trial;
        rss = r;
        break;
      }
    }
    if (evaluations) ++*evaluations;
    if (!improved || step.cwiseAbs().maxCoeff() < 1e-15) break;
  }
}

// Law part of theta (scaled units) from an LSQ or LB fit.
EmgVector fit_law_scaled(const EmgProblem& pr, DampingEstimator estimator, int* evaluations) {
  const std::size_t n = pr.x.size();
  std::vector<std::size_t> order(n), hull;
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return pr.x[i] != pr.x[j] ? pr.x[i] < pr.x[j] : pr.y[i] < pr.y[j];
  });
  const bool lb = estimator == DampingEstimator::lb;
  EmgVector theta(law_param_count(pr.law));
  switch (pr.law) {
    case DampingKind::rayleigh: {
      const Line l = lb ? lower_bound_line(pr.x, pr.y, order, hull) : least_squares_line(pr.x, pr.y, true);
      theta << l.intercept, l.slope;
      break;
    }
    case DampingKind::powerlaw: {
      if (lb) {  // log c = log alpha2 + alpha3 log lambda: a line in log-log space
        std::vector<double> log_y(n);
        for (std::size_t i = 0; i < n; ++i) log_y[i] = std::log(pr.y[i]);
        const Line l = lower_bound_line(pr.log_x, log_y, order, hull);
        theta << std::exp(l.intercept), l.slope;
      } else {
        std::vector<double> u(n);
        auto rss = [&](double p) {
          for (std::size_t i = 0; i < n; ++i) u[i] = std::exp(p * pr.log_x[i]);
          return least_squares_line(u, pr.y, false).objective;
        };
        const double p = minimise_exponent(rss, evaluations);
        rss(p);
        theta << least_squares_line(u, pr.y, false).slope, p;
        polish_least_squares(pr, theta, evaluations);
      }
      break;
    }
    case DampingKind::hybrid: {
      std::vector<double> u(n);
      // x^p keeps the order of x for p > 0, so `order` stays valid for the hull.
      auto fit_at = [&](double p) {
        for (std::size_t i = 0; i < n; ++i) u[i] = std::exp(p * pr.log_x[i]);
        return lb ? lower_bound_line(u, pr.y, order, hull) : least_squares_line(u, pr.y, true);
      };
      const double p = minimise_exponent([&](double q) { return fit_at(q).objective; }, evaluations);
      const Line l = fit_at(p);
      theta << l.intercept, l.slope, p;
      if (!lb) polish_least_squares(pr, theta, evaluations);
      break;
    }
    case DampingKind::constant_q:
    case DampingKind::relaxation: throw std::invalid_argument(to_string(pr.law) + " is not fitted");
  }
  return theta;
}


// Scaled model value y = m(x) of the law part of theta.
double scaled_model(const EmgProblem& pr, const EmgVector& theta, std::size_t i) {
  switch (pr.law) {
    case DampingKind::rayleigh: return theta[0] + theta[1] * pr.x[i];
    case DampingKind::powerlaw: return theta[0] * std::exp(theta[1] * pr.log_x[i]);
    default: return theta[0] + theta[1] * std::exp(theta[2] * pr.log_x[i]);
  }
}

double law_rss(const EmgProblem& pr, const EmgVector& theta) {
  double sum = 0.0;
  for (std::size_t i = 0; i < pr.x.size(); ++i) {
    const double r = pr.y[i] - scaled_model(pr, theta, i);
    sum += r * r;
  }
  return sum;
}

// Full EMG start from a law fit: eta from the spread of the residuals (the EMG's excess has mean
// 1/eta), sigma a quarter of it (measured damping is mostly one-sided; Sterling: sigma tends to be small).
EmgVector emg_start(const EmgProblem& pr, const EmgVector& law_theta) {
  const int k = law_param_count(pr.law);
  const std::size_t n = pr.x.size();
  double mean = 0.0, sq = 0.0;
  for (std::size_t i = 0; i < n; ++i) mean += pr.y[i] - scaled_model(pr, law_theta, i);
  mean /= double(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double d = pr.y[i] - scaled_model(pr, law_theta, i) - mean;
    sq += d * d;
  }
  const double spread = std::max(std::sqrt(sq / double(n)), 1e-6);
  EmgVector theta(k + 2);
  theta.head(k) = law_theta;
  theta[k] = std::log(0.25 * spread);
  theta[k + 1] = -std::log(spread);
  return theta;
}

struct NewtonResult {
  EmgVector theta;
  double loglik = -INFINITY;
  int iterations = 0;
  bool converged = false;
};

// Damped Newton ascent: solve (-H + mu I) d = g (mu = 0 when -H is positive definite), cap the step,
// backtrack until the Armijo condition holds. Stops when the Newton decrement g'd is below tolerance.
NewtonResult maximise_emg(const EmgProblem& pr, EmgVector theta, const DampingFitOptions& options) {
  NewtonResult res;
  EmgVector g, trial;
  EmgMatrix H;
  double f = emg_loglik_scaled(pr, theta, &g, &H);
  if (!std::isfinite(f)) return res;
  const int np = int(theta.size());
  for (int it = 0; it < options.max_iterations; ++it) {
    EmgMatrix M = -H;
    const double diag_scale = std::max(1e-12, M.diagonal().cwiseAbs().maxCoeff());
    double mu = 0.0;
    Eigen::LLT<EmgMatrix> llt;
    for (int attempt = 0; attempt < 60; ++attempt) {
      EmgMatrix shifted = M;
      shifted.diagonal().array() += mu;
      llt.compute(shifted);
      if (llt.info() == Eigen::Success) break;
      mu = mu == 0.0 ? 1e-10 * diag_scale : 4.0 * mu;
    }
    EmgVector d = llt.solve(g);
    const double decrement = g.dot(d);
    if (!(decrement >= 0) || !d.allFinite()) {  // numerically singular: fall back to the gradient
      d = g / diag_scale;
    }
    if (std::abs(decrement) < options.tolerance) {
      res.converged = true;
      break;
    }
    // sigma -> 0 with ascent continuing: the optimum is on the boundary (the EMG degenerates to a shifted
    // exponential, an LB-like fit); the likelihood has converged long before sigma' = 1e-12.
    if (theta[np - 2] < std::log(1e-12) && d[np - 2] < 0) {
      res.converged = true;
      break;
    }
    const double largest = d.cwiseAbs().maxCoeff();
    if (largest > 2.0) d *= 2.0 / largest;  // no step beyond e^2 in sigma/eta, 2 in scaled law units
    const double slope = g.dot(d);
    double step = 1.0, f_new = -INFINITY;
    bool accepted = false;
    for (int ls = 0; ls < 50; ++ls) {
      trial = theta + step * d;
      f_new = emg_loglik_scaled(pr, trial, nullptr, nullptr);
      if (std::isfinite(f_new) && f_new >= f + 1e-4 * step * slope) {
        accepted = true;
        break;
      }
      step *= 0.5;
    }
    ++res.iterations;
    if (!accepted) {  // no ascent possible at this precision: at the optimum up to rounding
      res.converged = std::abs(decrement) < 1e-6 * std::max(1.0, std::abs(f));
      break;
    }
    theta = trial;
    f = emg_loglik_scaled(pr, theta, &g, &H);
  }
  res.theta = theta;
  res.loglik = f;
  return res;
}

}  // namespace

DampingFit fit_damping(const std::vector<DampingPoint>& points, DampingKind law, DampingEstimator estimator,
                       const DampingFitOptions& options) {
  if (points.size() < damping_fit_param_count(law, estimator))
    throw std::invalid_argument("fit_damping: fewer points than parameters");
  const EmgProblem pr = make_emg_problem(points, law);
  DampingFit fit;
  fit.estimator = estimator;
  if (estimator != DampingEstimator::emg) {
    fit.law = law_from_scaled(pr, fit_law_scaled(pr, estimator, &fit.iterations));
    return fit;
  }
  int evaluations = 0;  // profile evaluations of the starts are not Newton iterations
  NewtonResult best;
  int iterations = 0;
  EmgProblem weighted = pr;
  // Relative noise: spread scales from a law (the model's value in scaled units, floored at 1 % of the
  // median c so a power law near lambda = 0 keeps a spread).
  const auto scales_from = [&](const DampingLaw& from_law) {
    weighted.noise_scale.clear();
    for (const DampingPoint& p : points)
      weighted.noise_scale.push_back(std::max(damping_c_per_s(from_law, p.lambda_rad2_s2) / pr.c_scale, 0.01));
  };
  const EmgVector lb_start = fit_law_scaled(pr, DampingEstimator::lb, &evaluations);
  if (options.relative_noise) scales_from(law_from_scaled(pr, lb_start));
  for (DampingEstimator start : {DampingEstimator::lb, DampingEstimator::lsq}) {
    const EmgVector law_start = start == DampingEstimator::lb ? lb_start : fit_law_scaled(pr, start, &evaluations);
    const NewtonResult r = maximise_emg(weighted, emg_start(pr, law_start), options);
    iterations += r.iterations;
    if (r.loglik > best.loglik) best = r;
  }
  if (options.relative_noise && best.theta.size() > 0) {  // once more with scales from the fitted law
    scales_from(law_from_scaled(pr, best.theta));
    best = maximise_emg(weighted, best.theta, options);
    iterations += best.iterations;
  }
  if (best.theta.size() == 0) {  // both starts non-finite: report the LB law, no likelihood
    fit.law = law_from_scaled(pr, fit_law_scaled(pr, DampingEstimator::lb, &evaluations));
    fit.converged = false;
    return fit;
  }
  const int k = law_param_count(law);
  fit.law = law_from_scaled(pr, best.theta);
  fit.sigma_per_s = pr.c_scale * std::exp(best.theta[k]);
  fit.eta_s = std::exp(best.theta[k + 1]) / pr.c_scale;
  fit.loglik = best.loglik - double(points.size()) * std::log(pr.c_scale);
  fit.iterations = iterations;
  fit.converged = best.converged;
  return fit;
}

}  // namespace ms
