// What the experimenter view draws for A/B and magnitude blocks, computed from the stored responses by
// the library statistics (the GUI only presents):
//   A/B: per pair of stimuli (either order) the proportion of the block's measure with its exact
//     binomial test and 95 % Clopper-Pearson interval (binomial_test.hpp). The measure follows the
//     answer: ABX "correct" (the chosen one is X, as the export's `correct` column), same/different
//     "different", A/B choices (preference, 2AFC) "chose <first stimulus of the pair>". Bipolar
//     scores are graded, not proportions, and are left out.
//   magnitude: the block's ratings normalised and aggregated by magnitude_estimation (modulus pair and
//     value from the protocol) into a dissimilarity matrix, mapped in 2 dimensions by classical MDS.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "analysis/stats/binomial_test.hpp"
#include "studyapp/core/protocol.hpp"
#include "studyapp/core/results_store.hpp"

namespace ms {

struct AbProportion {
  std::string first, second;  // the pair, in order of first appearance
  std::string measure;        // "correct", "different" or "chose <first>"
  BinomialTest test;          // successes of trials, proportion, p against 1/2, 95 % interval
};

// The rows of `block_id` (other rows are ignored); pairs in order of first appearance.
std::vector<AbProportion> ab_proportions(const std::vector<ResponseRow>& rows, const std::string& block_id);

struct MagnitudeMap {
  std::vector<std::string> labels;
  std::vector<double> x, y;  // classical MDS coordinates (dimension 1, 2), one per label
  std::size_t listeners = 0;
  std::string problem;       // why there is no map (e.g. a pair nobody rated), "" when there is one
};

// `protocol` supplies the block's modulus pair and value (nullptr: geometric-mean normalisation).
// Ratings of 0 of an identical pair ("no difference") carry no ratio and are left out.
MagnitudeMap magnitude_map(const std::vector<ResponseRow>& rows, const std::string& block_id, const Protocol* protocol);

}  // namespace ms
