// Trial scheduling (see schedule.hpp).
#include "studyapp/core/schedule.hpp"

#include <algorithm>
#include <cctype>

namespace ms {

std::uint64_t participant_seed(std::uint64_t protocol_seed, const std::string& participant) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a 64
  for (unsigned char c : participant) {
    h ^= c;
    h *= 1099511628211ull;
  }
  std::uint64_t z = protocol_seed ^ (h + 0x9e3779b97f4a7c15ull + (protocol_seed << 6) + (protocol_seed >> 2));
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;  // splitmix64 finaliser
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::uint64_t uniform_below(std::mt19937_64& engine, std::uint64_t n) {
  if (n <= 1) return 0;
  const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % n);  // reject the biased tail
  std::uint64_t x = engine();
  while (x >= limit) x = engine();
  return x % n;
}

std::vector<std::vector<std::size_t>> latin_square(std::size_t n) {
  std::vector<std::size_t> first;  // 0, 1, n-1, 2, n-2, ...
  for (std::size_t k = 0, lo = 1, hi = n; k < n; ++k) first.push_back(k == 0 ? 0 : (k % 2 == 1 ? lo++ : --hi));
  std::vector<std::vector<std::size_t>> rows(n, std::vector<std::size_t>(n));
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c) rows[r][c] = (first[c] + r) % n;
  return rows;
}

std::size_t latin_square_row(const std::string& participant, std::size_t n) {
  if (n == 0) return 0;
  std::size_t end = participant.size(), start = end;
  while (start > 0 && std::isdigit(static_cast<unsigned char>(participant[start - 1]))) --start;
  if (start < end && end - start <= 18) return std::stoull(participant.substr(start)) % n;
  return static_cast<std::size_t>(participant_seed(0, participant) % n);
}

namespace {

void add_pair_trials(std::vector<Trial>& out, const Trial& proto, const std::vector<StimulusPair>& pairs,
                     int repeats, bool randomize, bool abx, std::mt19937_64& rng) {
  for (int rep = 0; rep < repeats; ++rep)
    for (const auto& pr : pairs) {
      Trial t = proto;
      t.repeat = static_cast<std::size_t>(rep);
      t.stimuli = {pr[0].name, pr[1].name};
      if (randomize && uniform_below(rng, 2) == 1) {
        std::swap(t.stimuli[0], t.stimuli[1]);
        t.swapped = true;
      }
      if (abx) t.stimuli.push_back(t.stimuli[uniform_below(rng, 2)]);  // X is A or B
      out.push_back(t);
    }
}

// A, B, then the pair's reference.
void add_reference(Trial& t, const std::string& reference) {
  t.reference = reference;
  t.stimuli.push_back(reference);
}

void add_single_trials(std::vector<Trial>& out, const Trial& proto, const std::vector<StimulusRef>& stimuli,
                       int repeats) {
  for (int rep = 0; rep < repeats; ++rep)
    for (const auto& s : stimuli) {
      Trial t = proto;
      t.repeat = static_cast<std::size_t>(rep);
      t.stimuli = {s.name};
      out.push_back(t);
    }
}

std::vector<Trial> block_trials(const Block& b, std::size_t block_index, std::mt19937_64& rng) {
  Trial proto;
  proto.block = block_index;
  proto.block_id = b.id;
  proto.type = b.type;
  proto.training = b.training;
  std::vector<Trial> out;
  if (const auto* ab = std::get_if<AbBlock>(&b.body)) {
    add_pair_trials(out, proto, ab->pairs, b.repeats, b.randomize, ab->mode == AbMode::abx, rng);
    if (!ab->references.empty())  // trials come out pair by pair, repeat by repeat
      for (std::size_t k = 0; k < out.size(); ++k) add_reference(out[k], ab->references[k % ab->references.size()].name);
  } else if (const auto* m = std::get_if<MushraBlock>(&b.body)) {
    for (int rep = 0; rep < b.repeats; ++rep) {
      Trial t = proto;
      t.repeat = static_cast<std::size_t>(rep);
      if (m->reference) {
        t.reference = m->reference->name;
        t.stimuli.push_back(m->reference->name);  // the hidden reference
      }
      for (const auto& c : m->conditions) t.stimuli.push_back(c.name);
      for (const auto& a : m->anchors) t.stimuli.push_back(a.name);
      if (b.randomize) fisher_yates(t.stimuli, rng);
      out.push_back(t);
    }
  } else if (const auto* bs = std::get_if<Bs1116Block>(&b.body)) {
    // One trial per condition and repeat: A and B are the condition and the hidden reference, which
    // is which drawn per trial.
    for (int rep = 0; rep < b.repeats; ++rep)
      for (const auto& c : bs->conditions) {
        Trial t = proto;
        t.repeat = static_cast<std::size_t>(rep);
        t.reference = bs->reference.name;
        t.stimuli = {c.name, bs->reference.name};
        if (b.randomize && uniform_below(rng, 2) == 1) std::swap(t.stimuli[0], t.stimuli[1]);
        out.push_back(t);
      }
  } else if (const auto* g = std::get_if<MagnitudeBlock>(&b.body)) {
    std::vector<StimulusPair> pairs = g->pairs;
    if (g->all_pairs)
      for (std::size_t i = 0; i < g->stimuli.size(); ++i)
        for (std::size_t j = g->identical_pairs ? i : i + 1; j < g->stimuli.size(); ++j)
          pairs.push_back({g->stimuli[i], g->stimuli[j]});
    add_pair_trials(out, proto, pairs, b.repeats, b.randomize, false, rng);
  } else if (const auto* i = std::get_if<IdentifyBlock>(&b.body)) {
    add_single_trials(out, proto, i->stimuli, b.repeats);
  } else if (const auto* r = std::get_if<RatingBlock>(&b.body)) {
    add_single_trials(out, proto, r->stimuli, b.repeats);
  } else if (const auto* a = std::get_if<AdjustBlock>(&b.body)) {
    add_single_trials(out, proto, {a->paramset}, b.repeats);
  } else if (const auto* s = std::get_if<StaircaseBlock>(&b.body)) {
    // One trial per track; the track itself adapts at run time. Its stimuli: stimulus, reference.
    add_single_trials(out, proto, {s->stimulus}, b.repeats);
    for (auto& t : out) t.stimuli.push_back(s->reference ? s->reference->name : s->stimulus.name);
  } else if (const auto* l = std::get_if<LimitsBlock>(&b.body)) {
    // One trial per series (the block's repeats); the series descends at run time. Stimuli: stimulus, reference.
    add_single_trials(out, proto, {l->stimulus}, b.repeats);
    for (auto& t : out) t.stimuli.push_back(l->reference ? l->reference->name : l->stimulus.name);
  } else if (const auto* tk = std::get_if<TokensBlock>(&b.body)) {
    // One trial per series; the tokens compared are chosen at run time. Its stimulus: the one pruned.
    add_single_trials(out, proto, {tk->stimulus}, b.repeats);
  } else if (const auto* cp = std::get_if<ChangepointBlock>(&b.body)) {
    // One trial per sweep and repeat, its sounds in the written order (only the trials are shuffled).
    for (int rep = 0; rep < b.repeats; ++rep)
      for (const auto& sweep : cp->sweeps) {
        Trial t = proto;
        t.repeat = static_cast<std::size_t>(rep);
        for (const auto& sound : sweep) t.stimuli.push_back(sound.name);
        out.push_back(t);
      }
  } else {
    out.push_back(proto);  // instructions, questionnaire: one screen
  }
  // MUSHRA shuffles within the screen; other blocks shuffle the trial order.
  if (b.randomize && b.type != BlockType::mushra) fisher_yates(out, rng);
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].index = k;
    out[k].break_after = b.break_after > 0 && (k + 1) % static_cast<std::size_t>(b.break_after) == 0 &&
                         k + 1 < out.size();
  }
  return out;
}

// Each run of neighbouring blocks sharing a shuffle group takes an order of its own, drawn from a
// stream of its own (a protocol without groups keeps every draw it had).
void shuffle_groups(const Protocol& p, std::uint64_t seed, std::vector<std::size_t>& order) {
  std::mt19937_64 rng(seed ^ 0x53485546464c45ull);  // "SHUFFLE"
  for (std::size_t start = 0; start < order.size();) {
    const std::string& group = p.blocks[order[start]].shuffle;
    std::size_t end = start + 1;
    while (end < order.size() && !group.empty() && p.blocks[order[end]].shuffle == group) ++end;
    if (end - start > 1) {
      std::vector<std::size_t> run(order.begin() + static_cast<std::ptrdiff_t>(start),
                                   order.begin() + static_cast<std::ptrdiff_t>(end));
      fisher_yates(run, rng);  // the project's own draw: the same order with every standard library
      std::copy(run.begin(), run.end(), order.begin() + static_cast<std::ptrdiff_t>(start));
    }
    start = end;
  }
}

}  // namespace

Schedule make_schedule(const Protocol& p, const std::string& participant) {
  Schedule s;
  s.participant = participant;
  s.seed = participant_seed(p.seed, participant);
  std::mt19937_64 rng(s.seed);
  for (std::size_t i = 0; i < p.blocks.size(); ++i) s.block_order.push_back(i);
  if (p.counterbalance == Counterbalance::latin_square) {
    std::vector<std::size_t> slots;  // positions of the test blocks
    for (std::size_t i = 0; i < p.blocks.size(); ++i) {
      const auto& b = p.blocks[i];
      if (!b.training && b.type != BlockType::instructions && b.type != BlockType::questionnaire)
        slots.push_back(i);
    }
    if (slots.size() > 1) {
      const auto square = latin_square(slots.size());
      const auto& row = square[latin_square_row(participant, slots.size())];
      for (std::size_t k = 0; k < slots.size(); ++k) s.block_order[slots[k]] = slots[row[k]];
    }
  }
  shuffle_groups(p, s.seed, s.block_order);
  for (std::size_t bi : s.block_order) {
    if (p.blocks[bi].type == BlockType::unknown) continue;
    auto t = block_trials(p.blocks[bi], bi, rng);
    s.trials.insert(s.trials.end(), t.begin(), t.end());
  }
  return s;
}

}  // namespace ms
