// The adaptive token procedure of van den Doel et al. 2002, Experiment 2 ("finding the differentiable
// sounds"). The tokens of a sequence are one model with its first K modes of an ordering kept, K = from,
// from - 1, ..., to (the paper: 179 tokens for the vase, naive order, down to the one-mode token). The
// token of `from` modes starts as the reference and is compared with the next token (one mode fewer).
// A comparison heard as the same is discarded and the reference is compared with the token after it;
// the first comparison heard as different becomes the new reference. The series ends once the token of
// `to` modes has been compared: from - to comparisons, every token but the first compared exactly once.
//
// The distinguished tokens are the references in turn: the first one and every comparison heard as
// different. Their number lies in [1, from - to + 1]; the ceiling, the number of tokens, is the
// sequence's own (the paper's four: 179, 100, 128, 41), so counts of different sequences are not on one
// scale (Table 2 of the paper).
#pragma once
#include <cstddef>
#include <vector>

namespace ms {

class TokenSeries {
 public:
  // from > to >= 1 (std::invalid_argument otherwise).
  TokenSeries(int from, int to);

  int from() const { return from_; }
  int to() const { return to_; }
  int tokens() const { return from_ - to_ + 1; }          // the ceiling of distinguished()
  int reference() const { return reference_; }            // modes of the reference now
  int comparison() const;                                 // modes of the token compared next
  bool finished() const { return different_.size() == std::size_t(from_ - to_); }
  // The answer to comparison() against reference(); std::logic_error once finished.
  void record(bool different);

  // Per answered comparison, in order: the reference's and the comparison's modes, and the answer.
  const std::vector<int>& references() const { return references_; }
  std::vector<int> comparisons() const;
  const std::vector<bool>& different() const { return different_; }
  // The first reference and every comparison heard as different, in order (falling).
  std::vector<int> distinguished() const;

 private:
  int from_, to_, reference_;
  std::vector<int> references_;
  std::vector<bool> different_;
};

}  // namespace ms
