// ms::plots: the pictures of ModalStudy (MDS maps, confusion heat maps, MUSHRA box plots, line plots,
// damping-law scatters, masking plots) rendered headless to PNG or SVG from plain data (no analysis types).
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace ms::plots {

struct PlotOptions {
  int width_px = 800;
  int height_px = 600;
  std::string title;
  std::string x_label;  // empty: each plot's default, with units
  std::string y_label;
};

struct XY {
  double x = 0.0;
  double y = 0.0;
};

// A named curve or point set (legend entry + points in data units).
struct Series {
  std::string name;
  std::vector<XY> points;
};

// Every function writes `path` atomically (write to a temporary beside it, then rename): .png
// (antialiased, white background, exactly width_px x height_px) or .svg (same size, options.title as
// the document title). Another extension or a missing/unwritable folder throws ms::InputError naming
// the path, and no file is left. Inconsistent inputs (vectors of different lengths) throw
// std::invalid_argument. Non-finite values are not drawn. A QApplication is created if none exists
// (platform "offscreen" when there is no DISPLAY / WAYLAND_DISPLAY); call from the main thread.

// Throws ms::InputError unless `path` ends in .png or .svg (case-insensitive). Returns true for SVG.
// Commands call it before any work, so a typo in -o fails fast.
bool check_output_path(const std::string& path);

// 1. MDS perceptual map: labelled points. With an overlay, a second map of the same stimuli (same
// order) is drawn with another marker, thin lines joining corresponding points, and a legend.
struct MapOverlay {
  std::vector<XY> points;           // one per base point
  std::vector<std::string> labels;  // optional (empty: no labels for the overlay)
  std::string name = "second map";  // legend
  std::string base_name = "map";    // legend entry of the base map
  bool procrustes_align = true;     // align to the base map first (see procrustes_align below)
};
void mds_map(const std::string& path, const std::vector<XY>& points, const std::vector<std::string>& labels,
             const PlotOptions& options, const std::optional<MapOverlay>& overlay = std::nullopt);

// Orthogonal Procrustes with scaling: the similarity transform s R y + t (R a rotation or reflection,
// s > 0) of `source` closest to `target` in summed squared distance (Gower 1975). Same lengths; with
// fewer than 2 distinct points only the translation is fitted. MDS maps are defined up to exactly
// these transforms, so two maps are compared after this alignment.
std::vector<XY> procrustes_align(const std::vector<XY>& target, const std::vector<XY>& source);

// 2. Confusion matrix as a heat map: matrix_percent[truth][response] (rows = truth on y, columns =
// response on x, both in `labels` order), cells coloured white -> dark blue over 0-100 % with the
// number printed in each cell, and a colour bar.
void confusion_heatmap(const std::string& path, const std::vector<std::string>& labels,
                       const std::vector<std::vector<double>>& matrix_percent, const PlotOptions& options);

// The rectangle (pixels, origin top-left) of cell (row, col) of that heat map at options' size, so a
// caller (the GUI's hover tooltips, the tests) can find a cell.
struct RectPx {
  double x = 0, y = 0, width = 0, height = 0;
};
RectPx confusion_cell_rect(const std::vector<std::string>& labels, const PlotOptions& options,
                           std::size_t row, std::size_t col);

// 3. MUSHRA: one box per condition (median, quartiles, whiskers to the furthest rating within 1.5 IQR,
// outliers as circles) on a 0-100 axis, with the mean (diamond) and its 95 % CI (bar) beside each box.
// All vectors have one entry per condition; ratings may be empty, means/CIs NaN (then not drawn).
void mushra_boxplot(const std::string& path, const std::vector<std::string>& conditions,
                    const std::vector<std::vector<double>>& ratings, const std::vector<double>& means,
                    const std::vector<double>& ci_low, const std::vector<double>& ci_high,
                    const PlotOptions& options);

// 4. Lines with markers, one per series (e.g. perceived difference vs number of modes). log_x: base-10
// axis, points with x <= 0 are not drawn.
void line_plot(const std::string& path, const std::vector<Series>& series, const PlotOptions& options,
               bool log_x = false);

// 5. Damping features (lambda [(rad/s)^2], c = 2d [1/s]) as points, with fitted laws as curves sampled
// by the caller. log_log: base-10 axes; non-positive values are not drawn.
void damping_scatter(const std::string& path, const std::vector<double>& lambda_rad2_s2,
                     const std::vector<double>& c_per_s, const std::vector<Series>& fitted_laws,
                     const PlotOptions& options, bool log_log = true);

// 6. Masking: each mode's level as a stem (kept and dropped in two colours), the masking threshold it
// sees and the threshold in quiet at its frequency as curves, on a log-frequency axis [Hz].
// One entry per mode; -inf levels/thresholds (silent mode, no masker) are not drawn.
void masking_plot(const std::string& path, const std::vector<double>& freq_hz,
                  const std::vector<double>& level_db, const std::vector<double>& masking_threshold_db,
                  const std::vector<double>& quiet_threshold_db, const std::vector<bool>& kept,
                  const PlotOptions& options);

// 7. Audit residual map: diff_db_by_band[band][frame] (model - measured, dB; NaN = below the floor in
// both, drawn grey) over [0, duration_s], diverging colours saturating at +-limit_db, with a colour bar.
void residual_map(const std::string& path, const std::vector<std::vector<double>>& diff_db_by_band,
                  double duration_s, double limit_db, const PlotOptions& options);
// 8. Loudness image sone_by_band[band][frame] (bands of band_bark Bark, frames hop_s apart); difference: a signed difference on a diverging scale.
void loudness_image(const std::string& path, const std::vector<std::vector<double>>& sone_by_band, double hop_s, double band_bark, bool difference, const PlotOptions& options);

}  // namespace ms::plots
