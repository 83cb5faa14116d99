// Magnitude estimation of dissimilarity (Stevens 1956; Carvellas & Schneider 1971), as in
// Experiment 3 of van den Doel et al. (2002): every listener rates every pair of tokens (identical
// pairs included: 12 tokens give 78 pairs) by a number whose ratio to the modulus pair's value (10)
// is the ratio of the dissimilarities. The ratings become a dissimilarity matrix for MDS.
//
// 1. Normalisation, per listener l (ratings r_lk > 0; a rating <= 0 is an input error):
//    - with a modulus pair (A, B) (either order): m_l = geometric mean of l's ratings of (A, B);
//      r'_lk = r_lk * 10 / m_l, so the modulus pair is rated 10 by everyone (a listener who never
//      rated the modulus pair is an error);
//    - without one ("modulus equalisation", Lane, Catania & Stevens 1961): g_l = geometric mean of
//      all of l's ratings, G = geometric mean of all ratings of all listeners; r'_lk = r_lk * G / g_l,
//      so every listener's ratings have the same geometric mean G (the data's own unit is kept).
//    factor_l is the multiplier (10 / m_l or G / g_l).
// 2. Aggregation: for pair {i, j} (both orders pooled), the geometric mean of each listener's
//    normalised ratings of it, then the geometric mean over the listeners who rated it (each
//    listener weighs the same; geometric means because magnitude estimates are log-normal, ratio
//    scaled; Stevens 1956).
// 3. The matrix: symmetric, zero diagonal, over all tokens in order of first appearance; a pair of
//    distinct tokens nobody rated is an error naming the pair. Ratings of identical pairs (i, i) are
//    used in the normalisation and reported (self_ratings) but do not enter the matrix.
#pragma once
#include <Eigen/Dense>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "synthesis/tidy_csv.hpp"

namespace ms {

struct MagnitudeColumns {
  std::string subject, first, second, rating;
};

struct MagnitudeOptions {
  std::optional<std::pair<std::string, std::string>> modulus;  // (A, B); none: geometric-mean normalisation
  double modulus_value = 10;                                   // the number anchored to the modulus pair
};

struct MagnitudeListener {
  std::string subject;
  std::size_t ratings = 0;
  double factor = 1;           // multiplier applied to this listener's ratings
  double modulus_rating = 0;   // m_l (geometric mean of the modulus pair's ratings); NaN without a modulus
  double geometric_mean = 0;   // g_l, of the raw ratings
};

struct MagnitudeEstimation {
  std::vector<std::string> labels;
  Eigen::MatrixXd dissimilarity;        // geometric means of the normalised ratings
  std::vector<MagnitudeListener> listeners;  // in order of first appearance
  std::vector<double> self_ratings;     // per label: geometric mean for (i, i); NaN if never rated
  bool modulus = false;                 // normalised by a modulus pair
  double grand_geometric_mean = 0;      // G, of all raw ratings
};

// Throws InputError (FILE:LINE:COLUMN) for unknown columns, empty labels, ratings <= 0, a modulus
// token that does not occur, a listener without a modulus rating, fewer than 3 tokens, or a missing pair.
MagnitudeEstimation magnitude_estimation(const TidyCsv& table, const MagnitudeColumns& columns,
                                         const MagnitudeOptions& options = {});

}  // namespace ms
