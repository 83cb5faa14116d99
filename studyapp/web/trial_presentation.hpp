// A trial as one participant's browser sees it: the page (block type, wording, choices, sliders) and
// its sounds under opaque ids drawn afresh for every trial (and every staircase step), so neither the
// page, the network nor the JS names a stimulus, its recipe hash, or which MUSHRA sound is the hidden
// reference or an anchor. The server keeps the other half: which id is which stimulus, what was heard.
//
// What this cannot hide, by choice: a MUSHRA hidden reference IS the open reference, so it is served
// as the same bytes (the cache's one file for that recipe). A script in the page could compare decoded
// buffers and find it. Disguising it (a per-serve dither, a gain, another encoding) would change what
// the listener hears and break the method's premise that the hidden reference is identical to the
// reference, so the audio stays identical and the leak is accepted: it needs deliberate scripting, not
// listening, and an honest participant's page never reads the samples. What is guaranteed (tests in
// tests/web/test_hidden_reference.cpp): the hidden reference's bytes equal the open reference's and no
// other condition's; every sound has its own id, drawn afresh at every sending (an old id is refused);
// the served files carry no name, recipe hash or metadata chunk; the page and JSON name no stimulus.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studyapp/core/session.hpp"
#include "studyapp/core/stimulus_cache.hpp"

namespace ms::web {

struct PresentedSound {
  std::string id;           // opaque, sent to the browser
  std::string label;        // what the participant reads ("A", "Reference", "Your sound")
  std::string name;         // logged with its events (never sent): the stimulus, or stimulus@level
  std::string stimulus;     // the cache's name of the stimulus (never sent)
  std::string hash;         // the cache's hash of its samples (never sent)
  std::vector<std::string> overrides;  // "key=value" on the stimulus (adjust variants, staircase levels)
  std::string detail_json;  // logged with its events (an adjust variant's slider values)
  bool heard = false;       // a play or switch of it was logged
};

struct Presentation {
  std::size_t trial = 0;    // Session::current_index()
  std::size_t step = 0;     // staircase, limits, tokens: steps taken in the track or series; 0 otherwise
  std::vector<PresentedSound> sounds;
  int plays = 0;            // play and switch events logged
  bool comparison_in_b = false;                // staircase: which interval holds the comparison
  std::size_t adjusted = 0;                    // adjust: index of the adjusted sound
  nlohmann::json adjusted_values;              // adjust: slider values of the sound last made
  nlohmann::json page;                         // sent to the browser (see page_json)
};

// Builds the presentation of the session's current trial (precondition: !session.finished()); renders
// through the cache what it needs (staircase comparison, adjust variant at the sliders' start).
Presentation present(Session& session, StimulusCache& cache);

// Adjust trials: makes the variant at slider positions 0..100 (one per slider, in order) and puts it
// in place of the adjusted sound under a new id (not heard yet). Throws std::invalid_argument for a
// wrong number of positions or one out of range.
void render_adjust_variant(Presentation& p, const Block& block, StimulusCache& cache, const std::vector<int>& positions);

// The page half of a presentation: what the browser shows for the session's current trial.
nlohmann::json page_json(Session& session, const Presentation& p, StimulusCache& cache);

// Where an adjust slider starts (0..100): where the parameter set puts its key, mid-range when unwritten.
int adjust_start_position(const StimulusCache& cache, const std::string& stimulus, const Slider& s);

// "key=value" as an override that reads back to the same double.
std::string override_text(const std::string& key, double value);

// The index of the sound with this id, or nullopt.
std::optional<std::size_t> find_sound(const Presentation& p, const std::string& id);

}  // namespace ms::web
