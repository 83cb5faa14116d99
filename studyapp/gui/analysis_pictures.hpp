// The experimenter view's pictures of a results database: per identify block the confusion heat map
// (stimulus x label, row percent), per MUSHRA block the box plot with means and 95 % CIs after BS.1534
// post-screening (core's mushra_boxes, the recipe of `stats mushra --plot`), per staircase block every
// session's track, per magnitude block the MDS map of the normalised ratings (core's magnitude_map), per
// A/B block each pair's proportion correct / different / preferred with its 95 % interval (core's
// ab_proportions), drawn with studyapp/plots from the stored responses.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "studyapp/core/protocol.hpp"

#include "studyapp/core/results_store.hpp"

namespace ms::gui {

struct Picture {
  std::string title;
  std::string path;      // PNG
  std::string svg_path;  // the same picture as SVG
};

// Writes the pictures into out_dir (which must exist); returns them in block order. `protocols` (study id
// -> protocol, see stored_protocols) gives magnitude blocks their modulus pair and value.
std::vector<Picture> draw_analysis_pictures(const std::vector<ResponseRow>& rows, const std::string& out_dir,
                                            const std::map<std::string, Protocol>& protocols = {});

}  // namespace ms::gui
