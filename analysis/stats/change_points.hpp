// Fig. 5.4 of Skandalou & Ireland 2017 (Experiment 3): each trial plays a sweep of one object's sounds
// with a parameter rising (Q from 1000 to 4600) and the listener marks the sounds at which the material
// changed. Per group (an object, or object and synthesis method), how many sweeps marked a change at
// each value of the parameter, out of how many sweeps heard, and the values marked most often (the
// thesis reads its material boundaries off these peaks: 1600, 3000, 3400/3600, 4000, and one at 2200).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "synthesis/tidy_csv.hpp"

namespace ms {

// Column names of a table with one row per sound of a sweep (the export's changepoint.csv).
struct ChangepointColumns {
  std::string value = "value", marked = "marked";
  std::vector<std::string> sweep{"participant", "block", "trial"};  // one sweep heard
  std::vector<std::string> by;                                      // groups; none: all sweeps together
};

struct ChangepointGroup {
  std::string name;                 // the `by` values joined by '/', "" without `by`
  std::size_t sweeps = 0;           // sweeps heard (with or without marks)
  std::vector<double> values;       // every value played in the group, rising
  std::vector<std::size_t> marks;   // per value: sweeps that marked a change there
  std::vector<double> most_chosen;  // the `top` values with most marks (ties at the cut kept), by count, then value
};

// Groups in order of first appearance. InputError at the cell for a value that is not a number,
// `marked` other than 0/1, a sweep that plays a value twice; "no data rows".
std::vector<ChangepointGroup> change_points_from_table(const TidyCsv& table, const ChangepointColumns& columns,
                                                       std::size_t top = 4);

}  // namespace ms
