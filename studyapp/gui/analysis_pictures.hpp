// The experimenter view's pictures of a results database: per identify block the confusion heat map
// (stimulus x label, row percent), per MUSHRA block the box plot with means and 95 % CIs after BS.1534
// post-screening (core's mushra_boxes, the recipe of `stats mushra --plot`), per staircase block every
// session's track, drawn with studyapp/plots from the stored responses.
#pragma once
#include <string>
#include <vector>

#include "studyapp/core/results_store.hpp"

namespace ms::gui {

struct Picture {
  std::string title;
  std::string path;      // PNG
  std::string svg_path;  // the same picture as SVG
};

// Writes the pictures into out_dir (which must exist); returns them in block order.
std::vector<Picture> draw_analysis_pictures(const std::vector<ResponseRow>& rows, const std::string& out_dir);

}  // namespace ms::gui
