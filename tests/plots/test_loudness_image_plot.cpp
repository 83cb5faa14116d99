// plots::loudness_image: cells coloured by loudness (white at 0 sone, dark red at the largest) or, for a
// difference, blue below and red above 0; a bad extension or ragged input writes nothing.
#include <gtest/gtest.h>

#include <QColor>
#include <QImage>

#include <filesystem>
#include <stdexcept>

#include "studyapp/plots/plots.hpp"
#include "synthesis/input_error.hpp"

namespace {

namespace fs = std::filesystem;

// The pixel at the centre of cell (band, frame) of an 800 x 600 picture without a title (the plot's
// grid spans x 60..700, y 10..550).
QColor cell(const QImage& image, std::size_t bands, std::size_t frames, std::size_t band, std::size_t frame) {
  const double w = 640.0 / double(frames), h = 540.0 / double(bands);
  return QColor(image.pixel(int(60 + (double(frame) + 0.5) * w), int(550 - (double(band) + 0.5) * h)));
}

fs::path temp(const std::string& name) { return fs::temp_directory_path() / ("ms_loudness_plot_" + name); }

}  // namespace

TEST(LoudnessImagePlot, LoudnessCellsFromWhiteToDarkRed) {
  const fs::path path = temp("image.png");
  const std::vector<std::vector<double>> sone = {{0.0, 1.0, 2.0, 4.0}, {4.0, 4.0, 4.0, 4.0}};
  ms::plots::loudness_image(path.string(), sone, 0.0116, 1.0, false, {});
  QImage image;
  ASSERT_TRUE(image.load(QString::fromStdString(path.string()), "PNG"));
  EXPECT_EQ(image.width(), 800);
  EXPECT_EQ(image.height(), 600);
  EXPECT_EQ(cell(image, 2, 4, 0, 0), QColor(255, 255, 255));
  EXPECT_EQ(cell(image, 2, 4, 1, 0), QColor(103, 0, 13));
  EXPECT_EQ(cell(image, 2, 4, 0, 3), QColor(103, 0, 13));
  // Half the maximum: half way from white to dark red, and louder cells are darker.
  EXPECT_EQ(cell(image, 2, 4, 0, 2), QColor(179, 128, 134));
  EXPECT_GT(cell(image, 2, 4, 0, 1).lightness(), cell(image, 2, 4, 0, 2).lightness());
  fs::remove(path);
}

TEST(LoudnessImagePlot, DifferenceIsBlueBelowAndRedAboveZero) {
  const fs::path path = temp("difference.png");
  const std::vector<std::vector<double>> diff = {{-2.0, 0.0, 2.0}};
  ms::plots::loudness_image(path.string(), diff, 0.0116, 1.0, true, {});
  QImage image;
  ASSERT_TRUE(image.load(QString::fromStdString(path.string()), "PNG"));
  EXPECT_EQ(cell(image, 1, 3, 0, 0), QColor(33, 102, 172));
  EXPECT_EQ(cell(image, 1, 3, 0, 1), QColor(255, 255, 255));
  EXPECT_EQ(cell(image, 1, 3, 0, 2), QColor(178, 24, 43));
  fs::remove(path);
}

TEST(LoudnessImagePlot, BadInputWritesNothing) {
  const fs::path jpg = temp("image.jpg"), png = temp("ragged.png");
  EXPECT_THROW(ms::plots::loudness_image(jpg.string(), {{1.0}}, 0.01, 1.0, false, {}), ms::InputError);
  EXPECT_THROW(ms::plots::loudness_image(png.string(), {{1.0, 2.0}, {1.0}}, 0.01, 1.0, false, {}),
               std::invalid_argument);
  EXPECT_THROW(ms::plots::loudness_image(png.string(), {}, 0.01, 1.0, false, {}), std::invalid_argument);
  EXPECT_FALSE(fs::exists(jpg));
  EXPECT_FALSE(fs::exists(png));
}
