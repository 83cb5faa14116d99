// Trial schedule: a protocol + participant id expanded into the ordered trial list. Seeded by
// hash(protocol seed, participant id) with std::mt19937_64 and our own Fisher–Yates, so the same
// inputs give the same schedule with every standard library.
#pragma once
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "studyapp/core/protocol.hpp"

namespace ms {

struct Trial {
  std::size_t block = 0;              // index into Protocol::blocks
  std::string block_id;
  BlockType type = BlockType::unknown;
  std::size_t index = 0;              // 0-based within the block
  std::size_t repeat = 0;             // 0-based repetition
  bool training = false;
  bool break_after = false;           // pause after this trial (block's break_after)
  std::vector<std::string> stimuli;   // presentation order: A,B (ab/magnitude; abx adds X), MUSHRA
                                      // hidden reference + conditions + anchors shuffled, or one stimulus
  std::string reference;              // MUSHRA open reference
  bool swapped = false;               // A/B order reversed with respect to the protocol's pair
};

struct Schedule {
  std::string participant;
  std::uint64_t seed = 0;             // the derived per-participant seed
  std::vector<std::size_t> block_order;
  std::vector<Trial> trials;
};

// splitmix64 of the protocol seed mixed with the FNV-1a hash of the participant id.
std::uint64_t participant_seed(std::uint64_t protocol_seed, const std::string& participant);

// Uniform integer in [0, n) by rejection (no std::uniform_int_distribution: it differs between
// standard libraries), and an in-place Fisher–Yates shuffle on top of it.
std::uint64_t uniform_below(std::mt19937_64& engine, std::uint64_t n);
template <class T>
void fisher_yates(std::vector<T>& v, std::mt19937_64& engine) {
  for (std::size_t i = v.size(); i > 1; --i) {
    const auto j = static_cast<std::size_t>(uniform_below(engine, i));
    std::swap(v[i - 1], v[j]);
  }
}

// Balanced (Williams) Latin square of order n: row r is 0, 1, n-1, 2, n-2, ... plus r (mod n). Every
// row and column holds each condition once; for even n each condition also precedes every other once.
std::vector<std::vector<std::size_t>> latin_square(std::size_t n);

// Row of the Latin square for a participant: the trailing digits of the id (P07 → 7) mod n, or the
// participant hash mod n for ids without trailing digits.
std::size_t latin_square_row(const std::string& participant, std::size_t n);

// With `counterbalance: latin_square`, the test blocks (not instructions, questionnaires or
// training blocks, which keep their places) are permuted among their positions by the row.
Schedule make_schedule(const Protocol& p, const std::string& participant);

}  // namespace ms
