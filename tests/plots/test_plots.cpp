// ms::plots: every plot kind as PNG (exact size, not blank) and SVG (well-formed, title and axis labels
// present); bad paths give InputError and leave no file; Procrustes alignment; `modalstudy plot`.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QImage>
#include <QSet>
#include <QXmlStreamReader>

#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <limits>

#include "studyapp/plots/plots.hpp"
#include "support/test_util.hpp"
#include "synthesis/input_error.hpp"

namespace {

namespace fs = std::filesystem;
using namespace ms::plots;
using ms::test::TempDir;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Distinct colours and the fraction of pixels that are not white.
struct PngStats {
  int width = 0, height = 0, colors = 0;
  double non_white = 0;
};
PngStats png_stats(const std::string& path) {
  QImage image;
  EXPECT_TRUE(image.load(QString::fromStdString(path), "PNG")) << path;
  PngStats s{image.width(), image.height(), 0, 0};
  QSet<QRgb> colors;
  long long non_white = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QRgb c = image.pixel(x, y);
      colors.insert(c);
      non_white += (c & 0xffffff) != 0xffffff;
    }
  s.colors = int(colors.size());
  s.non_white = double(non_white) / double(std::max(1, image.width() * image.height()));
  return s;
}

// All character data of a well-formed SVG document (fails the test when it is not well-formed).
std::string svg_text(const std::string& path) {
  const std::string bytes = slurp(path);
  QXmlStreamReader xml(QByteArray::fromStdString(bytes));
  std::string text;
  bool root_is_svg = false;
  while (!xml.atEnd()) {
    xml.readNext();
    if (xml.isStartElement() && !root_is_svg && xml.name() == QLatin1String("svg")) root_is_svg = true;
    if (xml.isCharacters()) text += xml.text().toString().toStdString() + "\n";
  }
  EXPECT_FALSE(xml.hasError()) << path << ": " << xml.errorString().toStdString();
  EXPECT_TRUE(root_is_svg) << path;
  return text;
}

// One call per plot kind, writing `path`, with the texts its SVG must contain.
struct Kind {
  std::string name;
  std::function<void(const std::string&, const PlotOptions&)> draw;
  std::vector<std::string> must_contain;  // besides the title
};

std::vector<Kind> kinds() {
  std::vector<Kind> k;
  k.push_back({"mds_map",
               [](const std::string& path, const PlotOptions& o) {
                 MapOverlay overlay;
                 overlay.points = {{2, 1}, {1, 2}, {-1, 0}, {0, -3}};
                 overlay.name = "model";
                 mds_map(path, {{0, 0}, {1, 0.5}, {-1, 1}, {0.3, -1}}, {"glass", "steel", "wood", "plastic"}, o,
                         overlay);
               },
               {"Dimension 1", "Dimension 2", "glass", "plastic", "model"}});
  k.push_back({"confusion_heatmap",
               [](const std::string& path, const PlotOptions& o) {
                 confusion_heatmap(path, {"glass", "metal", "wood"},
                                   {{80, 15, 5}, {10, 90, 0}, {0, 33.3, 66.7}}, o);
               },
               {"Response", "Presented (truth)", "metal", "66.7", "33.3"}});
  k.push_back({"mushra_boxplot",
               [](const std::string& path, const PlotOptions& o) {
                 mushra_boxplot(path, {"reference", "top 20", "anchor"},
                                {{100, 95, 98, 90, 97}, {70, 60, 82, 75, 5}, {20, 15, 30, 25, 10}},
                                {96, 58.4, 20}, {91, 25, 12}, {100, 92, 28}, o);
               },
               {"Condition", "Rating", "reference", "anchor"}});
  k.push_back({"line_plot",
               [](const std::string& path, const PlotOptions& o) {
                 PlotOptions with_labels = o;
                 with_labels.x_label = "Number of modes";
                 with_labels.y_label = "Perceived difference (0–100)";
                 line_plot(path, {{"plate", {{1, 80}, {10, 40}, {100, 5}}}, {"bar", {{1, 60}, {10, 20}, {100, 3}}}},
                           with_labels, true);
               },
               {"Number of modes", "Perceived difference", "plate", "bar"}});
  k.push_back({"damping_scatter",
               [](const std::string& path, const PlotOptions& o) {
                 std::vector<double> lambda, c;
                 for (int i = 1; i <= 30; ++i) {
                   const double omega = 2 * std::numbers::pi * 100.0 * i;
                   lambda.push_back(omega * omega);
                   c.push_back(4 + 1e-4 * std::pow(omega, 1.2) + (i % 5));
                 }
                 Series fit{"lsq", {}};
                 for (int i = 0; i <= 50; ++i) {
                   const double l = lambda.front() * std::pow(lambda.back() / lambda.front(), i / 50.0);
                   fit.points.push_back({l, 4 + 1e-4 * std::pow(l, 0.6)});
                 }
                 damping_scatter(path, lambda, c, {fit}, o, true);
               },
               {"(rad/s)²", "c = 2d", "1/s", "lsq"}});
  k.push_back({"masking_plot",
               [](const std::string& path, const PlotOptions& o) {
                 const double inf = std::numeric_limits<double>::infinity();
                 masking_plot(path, {200, 450, 470, 1200, 3100, 9000}, {60, 55, 38, 50, -inf, 30},
                              {40, 35, 45, 30, -inf, -inf}, {12, 6, 6, 2, -4, 12},
                              {true, true, false, true, false, false}, o);
               },
               {"Frequency [Hz]", "Level [dB SPL]", "threshold in quiet", "masking threshold", "kept", "dropped"}});
  return k;
}

TEST(Plots, EveryKindAsPngHasTheRequestedSizeAndIsNotBlank) {
  TempDir dir;
  for (const auto& kind : kinds()) {
    for (auto [w, h] : {std::pair{800, 600}, std::pair{640, 420}}) {
      PlotOptions o;
      o.width_px = w;
      o.height_px = h;
      o.title = "Title of " + kind.name;
      const std::string path = dir.file(kind.name + std::to_string(w) + ".png");
      kind.draw(path, o);
      const PngStats s = png_stats(path);
      EXPECT_EQ(s.width, w) << kind.name;
      EXPECT_EQ(s.height, h) << kind.name;
      EXPECT_GT(s.colors, 40) << kind.name;  // antialiased text, markers, several colours
      EXPECT_GT(s.non_white, 0.01) << kind.name;
      EXPECT_LT(s.non_white, 0.9) << kind.name;  // and a white background
    }
  }
  // No temporaries left behind.
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(Plots, EveryKindAsSvgIsWellFormedWithTitleAndAxisLabels) {
  TempDir dir;
  for (const auto& kind : kinds()) {
    PlotOptions o;
    o.title = "Title of " + kind.name + " <&>";  // must be escaped
    const std::string path = dir.file(kind.name + ".SVG");  // extension case does not matter
    kind.draw(path, o);
    const std::string raw = slurp(path);
    EXPECT_NE(raw.find("width=\"800"), std::string::npos) << kind.name;  // QSvgGenerator writes mm + viewBox
    EXPECT_NE(raw.find("viewBox=\"0 0 800 600\""), std::string::npos) << kind.name;
    const std::string text = svg_text(path);
    EXPECT_NE(text.find(o.title), std::string::npos) << kind.name;
    for (const auto& s : kind.must_contain) EXPECT_NE(text.find(s), std::string::npos) << kind.name << ": " << s;
  }
}

TEST(Plots, HeatmapCellsAreColouredByValue) {
  TempDir dir;
  const std::vector<std::string> labels = {"a", "b", "c"};
  const std::vector<std::vector<double>> m = {{100, 0, 50}, {25, 75, 0}, {0, 10, 90}};
  PlotOptions o;
  o.title = "cells";
  const std::string path = dir.file("heat.png");
  confusion_heatmap(path, labels, m, o);
  QImage image;
  ASSERT_TRUE(image.load(QString::fromStdString(path)));
  // A pixel near each cell's top-left corner (clear of the printed number and the grid lines).
  auto colour = [&](std::size_t r, std::size_t c) {
    const RectPx rect = confusion_cell_rect(labels, o, r, c);
    return QColor(image.pixel(int(rect.x + 5), int(rect.y + 5)));
  };
  const QColor full = colour(0, 0), none = colour(0, 1), half = colour(0, 2), most = colour(1, 1);
  EXPECT_GT(none.lightness(), 240);  // 0 %: nearly white
  EXPECT_LT(full.lightness(), 80);   // 100 %: dark
  EXPECT_LT(full.lightness(), most.lightness());
  EXPECT_LT(most.lightness(), half.lightness());
  EXPECT_LT(half.lightness(), none.lightness());
  EXPECT_EQ(colour(1, 2), colour(0, 1));  // equal values, equal colours
  EXPECT_NE(colour(2, 1), colour(0, 1));
  // The cells tile the grid row by row.
  const RectPx a = confusion_cell_rect(labels, o, 0, 0), b = confusion_cell_rect(labels, o, 1, 2);
  EXPECT_NEAR(b.x, a.x + 2 * a.width, 1e-9);
  EXPECT_NEAR(b.y, a.y + a.height, 1e-9);
}

TEST(Plots, BadExtensionOrFolderGivesInputErrorAndNoFile) {
  TempDir dir;
  PlotOptions o;
  o.title = "x";
  for (const std::string name : {"plot.jpg", "plot", "plot.png.txt"}) {
    const std::string path = dir.file(name);
    try {
      line_plot(path, {{"s", {{0, 1}, {1, 2}}}}, o);
      ADD_FAILURE() << "no InputError for " << name;
    } catch (const ms::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(".png or .svg"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(path));
  }
  EXPECT_THROW(check_output_path("a.pdf"), ms::InputError);
  EXPECT_FALSE(check_output_path("a.PNG"));
  EXPECT_TRUE(check_output_path("dir.png/a.svg"));

  const std::string missing = dir.file("no/such/folder/plot.png");
  EXPECT_THROW(confusion_heatmap(missing, {"a"}, {{100}}, o), ms::InputError);
  EXPECT_FALSE(fs::exists(dir.path() / "no"));

  if (::geteuid() != 0) {  // root writes anywhere
    const fs::path locked = dir.path() / "locked";
    fs::create_directories(locked);
    ::chmod(locked.c_str(), 0555);
    EXPECT_THROW(mushra_boxplot((locked / "m.svg").string(), {"a"}, {{50}}, {50}, {40}, {60}, o), ms::InputError);
    EXPECT_TRUE(fs::is_empty(locked));
    ::chmod(locked.c_str(), 0755);
  }
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, ::geteuid() != 0 ? 1u : 0u);
}

TEST(Plots, InconsistentInputsAreRejectedBeforeWriting) {
  TempDir dir;
  const std::string path = dir.file("x.png");
  EXPECT_THROW(confusion_heatmap(path, {"a", "b"}, {{1, 2}}, {}), std::invalid_argument);
  EXPECT_THROW(mds_map(path, {{0, 0}}, {"a", "b"}, {}), std::invalid_argument);
  EXPECT_THROW(masking_plot(path, {100}, {1, 2}, {1}, {1}, {true}, {}), std::invalid_argument);
  EXPECT_THROW(damping_scatter(path, {1, 2}, {1}, {}, {}), std::invalid_argument);
  EXPECT_FALSE(fs::exists(path));
  // Degenerate but valid data still draws.
  line_plot(path, {}, {});
  EXPECT_EQ(png_stats(path).width, 800);
  mushra_boxplot(path, {"empty"}, {{}}, {std::nan("")}, {std::nan("")}, {std::nan("")}, {});
  EXPECT_TRUE(fs::exists(path));
}

TEST(Plots, ProcrustesRecoversASimilarityTransform) {
  const std::vector<XY> target = {{0, 0}, {1, 0.5}, {-1, 1}, {0.3, -1}, {2, 2}};
  for (bool reflect : {false, true}) {
    std::vector<XY> source;
    const double angle = 0.7, scale = 2.5;
    for (const auto& p : target) {
      const double y = reflect ? -p.y : p.y;
      source.push_back({scale * (std::cos(angle) * p.x - std::sin(angle) * y) + 3,
                        scale * (std::sin(angle) * p.x + std::cos(angle) * y) - 1});
    }
    const auto aligned = procrustes_align(target, source);
    ASSERT_EQ(aligned.size(), target.size());
    for (std::size_t i = 0; i < target.size(); ++i) {
      EXPECT_NEAR(aligned[i].x, target[i].x, 1e-12) << reflect << " " << i;
      EXPECT_NEAR(aligned[i].y, target[i].y, 1e-12) << reflect << " " << i;
    }
  }
  // All source points equal: only the translation (onto the target's centroid).
  const auto same = procrustes_align({{0, 0}, {2, 0}}, {{5, 5}, {5, 5}});
  EXPECT_NEAR(same[0].x, 1, 1e-12);
  EXPECT_NEAR(same[1].y, 0, 1e-12);
  EXPECT_THROW(procrustes_align({{0, 0}}, {}), std::invalid_argument);
}

// ---- modalstudy plot ----

TEST(PlotCli, DemoWritesOnePictureOfEachKind) {
  TempDir dir;
  const auto r = ms::test::run_cli("plot demo -o '" + dir.file("pics") + "'", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  for (const char* name :
       {"mds_map", "confusion_heatmap", "mushra_boxplot", "line_plot", "damping_scatter", "masking_plot"}) {
    const PngStats s = png_stats(dir.file(std::string("pics/") + name + ".png"));
    EXPECT_EQ(s.width, 800) << name;
    EXPECT_EQ(s.height, 600) << name;
    EXPECT_GT(s.colors, 40) << name;
  }
  const auto svg = ms::test::run_cli("plot demo --format svg -o '" + dir.file("svg") + "'", dir);
  ASSERT_EQ(svg.exit_code, 0) << svg.err;
  EXPECT_NE(svg_text(dir.file("svg/masking_plot.svg")).find("Frequency [Hz]"), std::string::npos);
}

TEST(PlotCli, MaskingAndDampingFromFiles) {
  TempDir dir;
  const std::string modes = dir.write("modes.csv",
                                      "freq_hz,decay_per_s,amp\n"
                                      "220,3,1\n450,4,0.8\n470,4,0.05\n1300,6,0.4\n2900,9,0.01\n5100,14,0.2\n");
  auto r = ms::test::run_cli("plot masking '" + modes + "' -o '" + dir.file("m.svg") + "' --threshold-db 10 --playback-db 80", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = svg_text(dir.file("m.svg"));
  EXPECT_NE(text.find("modes.csv (a_v = 10 dB, 80 dB SPL)"), std::string::npos) << text;

  const std::string features = std::string(MODALSTUDY_TEST_DATA) + "/damping_fit/features.csv";
  for (const char* law : {"rayleigh", "hybrid", "powerlaw"}) {
    r = ms::test::run_cli("plot damping '" + features + "' --law " + law + " -o '" + dir.file(law) + ".png'", dir);
    ASSERT_EQ(r.exit_code, 0) << law << ": " << r.err;
    EXPECT_GT(png_stats(dir.file(law) + ".png").colors, 40) << law;
  }
  r = ms::test::run_cli("plot damping '" + features + "' --law hybrid --linear -o '" + dir.file("lin.svg") + "'", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string damping_text = svg_text(dir.file("lin.svg"));
  for (const char* s : {"lsq:", "lb:", "emg:", "c = 2d"}) EXPECT_NE(damping_text.find(s), std::string::npos) << s;
}

TEST(PlotCli, BadInputIsOneLineExitTwoAndNoFile) {
  TempDir dir;
  const std::string modes = dir.write("modes.csv", "freq_hz,decay_per_s,amp\n220,3,1\n450,0,0.8\n");
  const std::string features = std::string(MODALSTUDY_TEST_DATA) + "/damping_fit/features.csv";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"plot masking '" + modes + "' -o '" + dir.file("m.pdf") + "'", "m.pdf"},
      {"plot masking '" + dir.file("missing.csv") + "' -o '" + dir.file("m.png") + "'", "missing.csv"},
      {"plot masking '" + modes + "' -o '" + dir.file("m.png") + "'", "modes.csv:3"},  // decay 0
      {"plot masking '" + modes + "' -o '" + dir.file("m.png") + "' --threshold-db abc", "--threshold-db"},
      {"plot masking '" + modes + "' -o '" + dir.file("nowhere/m.png") + "' --threshold-db 99", "--threshold-db"},
      {"plot damping '" + features + "' --law viscous -o '" + dir.file("d.png") + "'", "viscous"},
      {"plot damping '" + features + "' --law hybrid -o '" + dir.file("nowhere/d.png") + "'", "nowhere"},
      {"plot demo -o '" + modes + "'", "modes.csv"},
  };
  for (const auto& [args, expected] : cases) {
    const auto r = ms::test::run_cli(args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(ms::test::count_lines(r.err), 1u) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err;
  }
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename(), "modes.csv") << "left behind: " << e.path();
}

}  // namespace
