// A webMUSHRA experiment config (its documented YAML: testname, testId and `pages` of the types
// generic, consent, volume, mushra, bs1116, paired_comparison, likert_single_stimulus,
// likert_multi_stimulus and finish, in nested lists that may start with "random") read as a
// ModalStudy protocol: the audio files become recordings, the pages become blocks.
//
//   generic, volume           instructions (the page's name and its HTML content as text)
//   consent                   instructions + a one-question questionnaire (mustConsent: "I agree" only)
//   mushra                    mushra (reference, conditions; createAnchor35 + createAnchor70 -> anchors:
//                             auto; one of them -> that low-passed reference as the anchor)
//   bs1116                    bs1116 (reference, conditions; each createAnchor35/70 adds that low-passed
//                             reference as a condition)
//   paired_comparison         ab, mode preference, one pair [reference, condition] per condition
//   likert_single_stimulus,   rating, one attribute named after the page, one point per response
//   likert_multi_stimulus     (the first and last response labels at the ends)
//   finish                    questionnaire (text, long_text and number as free text; likert as options)
//
// A random page group whose pages are one block each becomes a shuffle group.
// What a protocol cannot say (waveforms, loop ranges, random groups of nested lists, the unforced
// paired-comparison alternative, intermediate Likert labels) is one located note each; the import
// still succeeds. What cannot be read at all (bad YAML, an unknown page type, an audio file that is
// missing, outside webMUSHRA's root or not audio, sample rates that differ) is an InputError.
#pragma once
#include <string>
#include <vector>

namespace ms {

struct WebMushraImport {
  std::string protocol_yaml;       // parses and validates as a protocol written at the requested path
  std::vector<std::string> notes;  // file:line:column: what was not carried over, and why
};

// Audio paths resolve against webMUSHRA's root folder (configs live in <root>/configs/, and webMUSHRA
// resolves every path against <root>), falling back to the config's own folder; a path may not leave
// that folder. They are written relative to `protocol_path`'s folder.
WebMushraImport import_webmushra(const std::string& config_path, const std::string& protocol_path);

}  // namespace ms
