// `modalstudy fit-damping` end to end: JSON shape and values (equal to the library's fit), the readable
// table, --plot-data, and every kind of bad input: exit code 2, one stderr line naming file:line:column
// where it applies, nothing on stdout, no output file written.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "analysis/damping/damping_features.hpp"
#include "analysis/damping/damping_fit.hpp"

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int exit_code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

CliRun run_cli(const std::string& args) {
  const fs::path dir = fs::temp_directory_path() / ("ms_fit_damping_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string cmd = std::string("'") + MODALSTUDY_BIN + "' fit-damping " + args + " >'" +
                          (dir / "out").string() + "' 2>'" + (dir / "err").string() + "'";
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  fs::remove_all(dir);
  return r;
}

class FitDampingCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ms_fit_damping_cli_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  // Bad input: exit 2, exactly one stderr line starting "modalstudy: <where>", no stdout, no plot file.
  void expect_rejected(const std::string& args, const std::string& where, const std::string& problem) {
    const std::string plot = (dir_ / "plot.csv").string();
    const CliRun r = run_cli(args + " --json --plot-data '" + plot + "'");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.out, "");
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
    EXPECT_EQ(r.err.rfind("modalstudy: " + where + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(problem), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(plot));
  }
  fs::path dir_;
};

const std::string kFeatures = std::string(MODALSTUDY_TEST_DATA) + "/damping_fit/features.csv";

TEST_F(FitDampingCli, JsonMatchesLibraryFitForEveryLawAndEstimator) {
  const auto points = ms::damping_points(ms::read_damping_features_csv(kFeatures));
  for (const char* law : {"rayleigh", "powerlaw", "hybrid"})
    for (const char* est : {"emg", "lsq", "lb"}) {
      SCOPED_TRACE(std::string(law) + "/" + est);
      const CliRun r = run_cli("'" + kFeatures + "' --law " + law + " --estimator " + est + " --json");
      ASSERT_EQ(r.exit_code, 0) << r.err;
      ASSERT_EQ(r.out.find('\n'), r.out.size() - 1);  // one line, one object
      const auto j = nlohmann::json::parse(r.out);
      const ms::DampingFit fit = ms::fit_damping(points, ms::parse_damping_kind(law), ms::parse_damping_estimator(est));
      EXPECT_EQ(j.at("law"), law);
      EXPECT_EQ(j.at("estimator"), est);
      const auto& p = j.at("params");
      EXPECT_EQ(p.size(), std::string(law) == "hybrid" ? 3u : 2u);
      EXPECT_DOUBLE_EQ(p.at("beta").get<double>(), fit.law.alpha2);
      if (std::string(law) != "powerlaw") EXPECT_DOUBLE_EQ(p.at("alpha").get<double>(), fit.law.alpha1);
      if (std::string(law) != "rayleigh") EXPECT_DOUBLE_EQ(p.at("alpha3").get<double>(), fit.law.alpha3);
      if (std::string(est) == "emg") {
        EXPECT_DOUBLE_EQ(j.at("sigma").get<double>(), *fit.sigma_per_s);
        EXPECT_DOUBLE_EQ(j.at("eta").get<double>(), *fit.eta_s);
        EXPECT_DOUBLE_EQ(j.at("loglik").get<double>(), *fit.loglik);
      } else {
        EXPECT_TRUE(j.at("sigma").is_null() && j.at("eta").is_null() && j.at("loglik").is_null());
      }
      EXPECT_EQ(j.at("iterations").get<int>(), fit.iterations);
      EXPECT_GE(j.at("seconds").get<double>(), 0.0);
      EXPECT_LT(j.at("seconds").get<double>(), 1.0);
    }
}

TEST_F(FitDampingCli, TableAndPlotData) {
  const std::string plot = (dir_ / "plot.csv").string();
  const CliRun r = run_cli("'" + kFeatures + "' --law rayleigh --estimator lb --plot-data '" + plot + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("300 features"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("alpha   (alpha1) = "), std::string::npos) << r.out;
  // The plot data: one row per feature; LB residuals are all >= 0 (up to rounding) and the smallest is 0.
  std::ifstream in(plot);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "sound,freq_hz,lambda_rad2_s2,c_per_s,c_fit_per_s,residual_per_s\r");  // RFC 4180 CRLF
  int rows = 0;
  double min_residual = INFINITY;
  while (std::getline(in, line)) {
    ++rows;
    const double residual = std::stod(line.substr(line.rfind(',') + 1));
    min_residual = std::min(min_residual, residual);
  }
  EXPECT_EQ(rows, 300);
  EXPECT_NEAR(min_residual, 0.0, 1e-9);
  EXPECT_GT(min_residual, -1e-9);
}

TEST_F(FitDampingCli, MissingColumn) {
  const std::string f = write("f.csv", "sound,freq_hz,amp\na,100,1\n");
  expect_rejected("'" + f + "' --law rayleigh --estimator emg", f + ":1:1", "missing column 'decay_per_s'");
}

TEST_F(FitDampingCli, NaNCell) {
  const std::string f = write("f.csv", "sound,freq_hz,decay_per_s,amp\na,100,1,1\na,200,nan,1\n");
  expect_rejected("'" + f + "' --law rayleigh --estimator lsq", f + ":3:7", "not a finite number");
}

TEST_F(FitDampingCli, NegativeDecay) {
  const std::string f = write("f.csv", "freq_hz,decay_per_s\n100,1\n200,2\n300,-3\n");
  expect_rejected("'" + f + "' --law rayleigh --estimator lb", f + ":4:5", "decay_per_s must be greater than 0");
}

TEST_F(FitDampingCli, NonNumericCell) {
  const std::string f = write("f.csv", "sound,freq_hz,decay_per_s,amp\nsA,100,1,1\nsB,2k,2,1\n");
  expect_rejected("'" + f + "' --law hybrid --estimator lsq", f + ":3:4", "column 'freq_hz': expected a number, got '2k'");
}

TEST_F(FitDampingCli, FewerPointsThanParameters) {
  // emg + rayleigh estimates alpha, beta, sigma, eta: three features are not enough.
  const std::string f = write("f.csv", "freq_hz,decay_per_s\n100,1\n200,2\n300,3\n");
  expect_rejected("'" + f + "' --law rayleigh --estimator emg", f + ":4", "3 features, but the rayleigh law fitted by emg has 4 parameters");
  // ... while lsq with its two parameters accepts them.
  EXPECT_EQ(run_cli("'" + f + "' --law rayleigh --estimator lsq --json").exit_code, 0);
}

TEST_F(FitDampingCli, RelativeNoiseMatchesLibraryFit) {
  const auto points = ms::damping_points(ms::read_damping_features_csv(kFeatures));
  const CliRun r = run_cli("'" + kFeatures + "' --law rayleigh --estimator emg --noise relative --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ms::DampingFitOptions relative;
  relative.relative_noise = true;
  const ms::DampingFit fit = ms::fit_damping(points, ms::DampingKind::rayleigh, ms::DampingEstimator::emg, relative);
  EXPECT_EQ(j.at("noise"), "relative");
  EXPECT_DOUBLE_EQ(j.at("params").at("alpha").get<double>(), fit.law.alpha1);
  EXPECT_DOUBLE_EQ(j.at("loglik").get<double>(), *fit.loglik);
  const ms::DampingFit constant = ms::fit_damping(points, ms::DampingKind::rayleigh, ms::DampingEstimator::emg);
  EXPECT_NE(fit.law.alpha1, constant.law.alpha1);  // a different model, not the default under another name
}

TEST_F(FitDampingCli, MissingFile) {
  const std::string f = (dir_ / "nope.csv").string();
  expect_rejected("'" + f + "' --law rayleigh --estimator emg", f, "no such file");
}

TEST_F(FitDampingCli, UnknownLawAndEstimator) {
  expect_rejected("'" + kFeatures + "' --law quadratic --estimator emg", "--law", "unknown law 'quadratic'");
  expect_rejected("'" + kFeatures + "' --law constant_q --estimator emg", "--law", "unknown law 'constant_q'");
  expect_rejected("'" + kFeatures + "' --law rayleigh --estimator mle", "--estimator", "unknown estimator 'mle'");
  expect_rejected("'" + kFeatures + "' --law rayleigh --estimator emg --noise loud", "--noise", "unknown noise model 'loud'");
  expect_rejected("'" + kFeatures + "' --law rayleigh --estimator lb --noise relative", "--noise",
                  "applies to --estimator emg only");
}

}  // namespace
