// Whether a trial's answer may be sent yet, and what the participant still has to do when it may not:
// hear every sound (the block's `listen_all`, on by default for every block type), in MUSHRA move every
// slider (webMUSHRA's rule: an untouched 0 is not a rating), and give a complete answer.
#pragma once
#include <string>
#include <vector>

#include "studyapp/core/protocol.hpp"

namespace ms {

// What the participant has done in the trial so far, as the view sees it.
struct TrialInputs {
  std::vector<bool> heard;    // per sound the view offers (MUSHRA: reference, A, B, ...)
  std::vector<bool> moved;    // MUSHRA: per slider, moved at least once
  bool complete = false;      // the widgets hold a whole answer (a choice made, a valid number typed)
  std::string why_incomplete; // the view's own reason when !complete ("" = the block type's wording)
};

struct AnswerGate {
  bool may_send = false;
  std::string missing;        // participant-facing: what is still to do ("" when may_send)
};

AnswerGate answer_gate(const Block& block, const TrialInputs& inputs);

}  // namespace ms
