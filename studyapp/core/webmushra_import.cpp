// webMUSHRA config -> protocol; see webmushra_import.hpp. The output is built as a YAML tree, emitted
// with yaml-cpp, then parsed and validated by the protocol's own reader before it is returned.
#include "studyapp/core/webmushra_import.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>

#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/bounded_file.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/yaml_reader.hpp"

namespace fs = std::filesystem;

namespace ms {

namespace {

const std::vector<std::string> kPageTypes{"generic", "consent", "volume", "mushra", "bs1116", "paired_comparison",
                                          "likert_single_stimulus", "likert_multi_stimulus", "finish"};

// The keys webMUSHRA's documentation gives each page type (and `type`).
const std::map<std::string, std::vector<std::string>>& page_keys() {
  static const std::map<std::string, std::vector<std::string>> k{
      {"generic", {"type", "id", "name", "content"}},
      {"consent", {"type", "id", "name", "content", "mustConsent"}},
      {"volume", {"type", "id", "name", "content", "stimulus", "defaultVolume"}},
      {"mushra", {"type", "id", "name", "content", "showWaveform", "enableLooping", "strict", "reference",
                  "createAnchor35", "createAnchor70", "randomize", "showConditionNames", "stimuli", "switchBack"}},
      {"bs1116", {"type", "id", "name", "content", "showWaveform", "enableLooping", "reference", "createAnchor35",
                  "createAnchor70", "stimuli"}},
      {"paired_comparison", {"type", "id", "name", "unforced", "content", "showWaveform", "enableLooping",
                             "reference", "stimuli"}},
      {"likert_single_stimulus", {"type", "id", "name", "content", "showWaveform", "mustRate", "mustPlayback",
                                  "stimuli", "maxStimuli", "response"}},
      {"likert_multi_stimulus", {"type", "id", "name", "content", "mustRate", "mustPlayback", "stimuli", "response"}},
      {"finish", {"type", "id", "name", "content", "popupContent", "showResults", "showErrors", "writeResults",
                  "questionnaire"}}};
  return k;
}

// Page HTML as the plain text an instructions block shows: tags dropped, <br>, <p> and </p> as line
// breaks, the XML entities and &nbsp; decoded, runs of blanks folded.
std::string html_text(const std::string& html) {
  std::string text;
  for (std::size_t i = 0; i < html.size();) {
    if (html[i] == '<') {
      const std::size_t end = html.find('>', i);
      if (end == std::string::npos) break;
      std::string tag = html.substr(i + 1, end - i - 1);
      std::transform(tag.begin(), tag.end(), tag.begin(), [](unsigned char c) { return std::tolower(c); });
      if (tag.rfind("br", 0) == 0 || tag == "p" || tag.rfind("p ", 0) == 0 || tag == "/p") text += '\n';
      i = end + 1;
      continue;
    }
    static const std::pair<const char*, const char*> kEntities[] = {
        {"&amp;", "&"}, {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&nbsp;", " "}};
    bool entity = false;
    for (const auto& [code, ch] : kEntities)
      if (html.compare(i, std::char_traits<char>::length(code), code) == 0) {
        text += ch;
        i += std::char_traits<char>::length(code);
        entity = true;
        break;
      }
    if (!entity) text += html[i++];
  }
  std::string folded;
  for (char c : text) {
    const bool blank = c == ' ' || c == '\t';
    if (blank && (folded.empty() || folded.back() == ' ' || folded.back() == '\n')) continue;
    if (c == '\n') {
      while (!folded.empty() && folded.back() == ' ') folded.pop_back();
      if (folded.empty() || (folded.size() >= 2 && folded.substr(folded.size() - 2) == "\n\n")) continue;
    }
    folded += blank ? ' ' : c;
  }
  while (!folded.empty() && (folded.back() == ' ' || folded.back() == '\n')) folded.pop_back();
  return folded;
}

// A webMUSHRA name (condition key, page id, question name) as a protocol id (is_identifier).
std::string as_id(const std::string& name, const std::string& fallback) {
  std::string id;
  for (char c : name) id += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
  while (!id.empty() && !std::isalnum(static_cast<unsigned char>(id.front()))) id.erase(id.begin());
  if (id.size() > 64) id.resize(64);
  return id.empty() ? fallback : id;
}

YAML::Node flow(YAML::Node n) {
  n.SetStyle(YAML::EmitterStyle::Flow);
  return n;
}

class Importer {
 public:
  Importer(const std::string& config_path, const std::string& protocol_path)
      : r_(config_path), protocol_path_(protocol_path) {
    config_dir_ = fs::absolute(fs::path(config_path)).parent_path();
    root_ = config_dir_.parent_path();
    protocol_dir_ = fs::absolute(fs::path(protocol_path)).parent_path();
  }

  WebMushraImport run(const std::string& text) {
    const YAML::Node root = r_.load(text);
    if (!root.IsMap()) r_.fail(root, "", "a webMUSHRA config is a map with testname, testId and pages");
    for (auto it = root.begin(); it != root.end(); ++it) {
      const std::string key = it->first.Scalar();
      static const std::set<std::string> kTop{"testname", "testId", "bufferSize", "stopOnErrors",
                                              "showButtonPreviousPage", "remoteService", "pages", "language"};
      if (!kTop.count(key)) note(it->first, key, "not a top-level key of a webMUSHRA config; ignored");
    }
    if (!root["pages"]) r_.fail(root, "", "missing 'pages' (the experiment's pages)");
    const std::string fallback = as_id(fs::path(r_.file()).stem().string(), "webmushra");
    std::string study = fallback;
    if (root["testId"]) study = as_id(r_.text(root["testId"], "testId"), fallback);
    else note(root, "testId", "missing: the study id is the config's file name, '" + fallback + "'");
    out_["study"] = study;
    out_["title"] = root["testname"] ? r_.text(root["testname"], "testname") : study;
    if (is_true(root["showButtonPreviousPage"]))
      note(root["showButtonPreviousPage"], "showButtonPreviousPage",
           "not carried over: an answered trial is committed and cannot be revisited");
    if (root["remoteService"])
      note(root["remoteService"], "remoteService", "not carried over: answers go to the study's results store");
    pages(root["pages"], "pages");
    if (blocks_.size() == 0) r_.fail(root["pages"], "pages", "no page becomes a block");

    if (sample_rate_hz_ > 0) out_["sample_rate"] = sample_rate_hz_;
    if (allow_outside_) out_["allow_outside"] = true;
    out_["stimuli"] = stimuli_;
    out_["blocks"] = blocks_;
    YAML::Emitter e;
    e << out_;
    WebMushraImport result{std::string(e.c_str()) + "\n", notes_};
    check(result.protocol_yaml);
    return result;
  }

 private:
  // The protocol reader and validator read the output as the file it will be (nothing stored).
  void check(const std::string& yaml) const {
    std::vector<std::string> problems;
    const Protocol p = parse_protocol(yaml, protocol_path_, protocol_dir_.string(), &problems);
    for (const std::string& q : validate_protocol(p)) problems.push_back(q);
    if (!problems.empty())
      throw InputError(SourceLocation{r_.file(), 0, 0}, "the imported protocol does not validate: " + problems.front());
  }

  void note(const YAML::Node& node, const std::string& path, const std::string& text) {
    notes_.push_back(InputError(r_.where(node, path), path + ": " + text).what());
  }

  bool is_true(const YAML::Node& n) const { return n && n.IsScalar() && n.Scalar() == "true"; }

  // A pages list: page maps, nested lists, and "random" as a list's first element.
  void pages(const YAML::Node& list, const std::string& path, int depth = 0) {
    if (!list.IsSequence()) r_.fail(list, path, "expected a list of pages");
    if (depth > 8) r_.fail(list, path, "page lists nested more than 8 deep");
    const bool random = list.size() > 0 && list[0].IsScalar() && list[0].Scalar() == "random";
    const std::size_t first_block = blocks_.size();
    bool one_block_per_page = true;
    for (std::size_t i = random ? 1 : 0; i < list.size(); ++i) {
      const std::string p = path + "[" + std::to_string(i) + "]";
      const YAML::Node item = list[i];
      const std::size_t before = blocks_.size();
      if (item.IsSequence()) pages(item, p, depth + 1);
      else if (item.IsMap()) page(item, p);
      else r_.fail(item, p, "expected a page (a map with 'type'), a list of pages, or \"random\" first in a list");
      one_block_per_page = one_block_per_page && item.IsMap() && blocks_.size() == before + 1;
    }
    if (!random) return;
    // webMUSHRA draws the order of a random group's pages per participant; so does a shuffle group.
    if (one_block_per_page) {
      const std::string group = "random-" + std::to_string(++random_groups_);
      for (std::size_t k = first_block; k < blocks_.size(); ++k) blocks_[k]["shuffle"] = group;
    } else {
      note(list[0], path + "[0]", "random page order not carried over: a page of this group is a nested list or "
                                  "not one block, so these pages run in the written order");
    }
  }

  void page(const YAML::Node& n, const std::string& p) {
    if (!n["type"]) r_.fail(n, p, "missing 'type' (one of generic, consent, volume, mushra, ...)");
    const std::string type = r_.text(n["type"], p + ".type");
    const auto keys = page_keys().find(type);
    if (keys == page_keys().end()) {
      const std::string near = nearest_key(type, kPageTypes);
      r_.fail(n["type"], p + ".type", "unknown page type '" + type + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)"));
    }
    for (auto it = n.begin(); it != n.end(); ++it) {
      const std::string key = it->first.Scalar();
      if (std::find(keys->second.begin(), keys->second.end(), key) == keys->second.end())
        note(it->first, p + "." + key, "not a key of a " + type + " page; ignored");
    }
    if (is_true(n["showWaveform"])) note(n["showWaveform"], p + ".showWaveform", "not carried over: no waveform is shown");
    if (is_true(n["enableLooping"]))
      note(n["enableLooping"], p + ".enableLooping", "not carried over: no loop range can be set (sounds play whole)");
    if (type == "generic" || type == "volume") instructions(n, p, type);
    else if (type == "consent") consent(n, p);
    else if (type == "mushra") mushra(n, p);
    else if (type == "bs1116") bs1116(n, p);
    else if (type == "paired_comparison") paired(n, p);
    else if (type == "finish") finish(n, p);
    else likert(n, p, type);
  }

  // The page's id as a block id, unique in the protocol.
  std::string page_id(const YAML::Node& n, const std::string& p, const std::string& type, bool take = true) {
    std::string id = as_id(n["id"] ? r_.text(n["id"], p + ".id") : type, type);
    std::string unique = id;
    for (int k = 2; block_ids_.count(unique); ++k) unique = id + "-" + std::to_string(k);
    if (take) block_ids_.insert(unique);
    return unique;
  }

  std::string content(const YAML::Node& n, const std::string& p) const {
    return n["content"] && !n["content"].IsNull() ? html_text(r_.text(n["content"], p + ".content")) : "";
  }

  YAML::Node block(const std::string& type, const std::string& id) {
    YAML::Node b;
    b["type"] = type;
    b["id"] = id;
    return b;
  }

  void instructions(const YAML::Node& n, const std::string& p, const std::string& type) {
    YAML::Node b = block("instructions", page_id(n, p, type));
    std::string text = n["name"] ? r_.text(n["name"], p + ".name") : "";
    const std::string body = content(n, p);
    text += (text.empty() || body.empty() ? "" : "\n\n") + body;
    b["text"] = text.empty() ? std::string(" ") : text;
    if (type == "volume")
      note(n["type"], p + ".type", "volume page: its text is shown; the level is the booth's calibrated playback level");
    blocks_.push_back(b);
  }

  void consent(const YAML::Node& n, const std::string& p) {
    instructions(n, p, "consent");
    YAML::Node q;
    q["id"] = "consent";
    q["text"] = "Do you consent?";
    YAML::Node options = flow(YAML::Node(YAML::NodeType::Sequence));
    options.push_back("I agree");
    if (!is_true(n["mustConsent"])) options.push_back("I do not agree");
    q["options"] = options;
    YAML::Node b = block("questionnaire", page_id(n, p, "consent"));
    b["questions"].push_back(q);
    blocks_.push_back(b);
  }

  // A recording named `preferred` (made unique when the name already holds another file).
  std::string stimulus(const YAML::Node& path_node, const std::string& p, const std::string& preferred,
                       const std::string& page) {
    const std::string written = r_.text(path_node, p);
    const fs::path rel(written);
    if (rel.is_absolute() || written.find("://") != std::string::npos)
      r_.fail(path_node, p, "'" + written + "' must be a path relative to webMUSHRA's root folder");
    fs::path found;
    std::error_code ec;
    for (const fs::path& base : {root_, config_dir_}) {
      const fs::path candidate = fs::weakly_canonical(base / rel, ec);
      const std::string inside = ec ? "" : fs::relative(candidate, fs::weakly_canonical(base, ec), ec).string();
      if (ec) r_.fail(path_node, p, "'" + written + "' is not a usable path: " + ec.message());
      if (inside.empty() || inside.rfind("..", 0) == 0)
        r_.fail(path_node, p, "'" + written + "' leaves webMUSHRA's root folder " + base.string());
      if (fs::is_regular_file(candidate, ec)) {
        found = candidate;
        break;
      }
    }
    if (found.empty())
      r_.fail(path_node, p, "audio file '" + written + "' not found under " + root_.string() + " or " + config_dir_.string());
    // Each file is read once, however many pages name it.
    double& rate = rates_hz_[found];
    if (rate == 0) try {
        rate = read_audio(found.string()).sample_rate_hz;
      } catch (const InputError& e) {
        r_.fail(path_node, p, e.problem());
      }
    if (sample_rate_hz_ == 0) sample_rate_hz_ = rate;
    else if (rate != sample_rate_hz_)
      r_.fail(path_node, p, "'" + written + "' is sampled at " + std::to_string(int(rate)) + " Hz, the files before it at " +
                                std::to_string(int(sample_rate_hz_)) + " Hz: a study plays at one rate");
    const std::string base_name = as_id(preferred, "stimulus");
    std::string name = base_name;
    const auto other_file = [&](const std::string& n) { return files_.count(n) && files_[n] != found; };
    if (other_file(name)) {
      name = base_name + "_" + page;
      for (int k = 2; other_file(name); ++k) name = base_name + "_" + page + "_" + std::to_string(k);
      note(path_node, p, "stimulus '" + preferred + "' is named '" + name + "': '" + base_name + "' is another file");
    }
    if (!files_.count(name)) {
      files_[name] = found;
      std::string out = fs::relative(found, fs::weakly_canonical(protocol_dir_, ec), ec).generic_string();
      if (ec || out.empty()) r_.fail(path_node, p, "cannot be written relative to " + protocol_dir_.string());
      if (out.rfind("..", 0) == 0) allow_outside_ = true;
      YAML::Node s;
      s["file"] = out;
      stimuli_[name] = flow(s);
    }
    return name;
  }

  std::vector<std::string> conditions(const YAML::Node& n, const std::string& p, const std::string& page) {
    const YAML::Node st = n["stimuli"];
    if (!st || !st.IsMap() || st.size() == 0) r_.fail(st ? st : n, p + ".stimuli", "expected a map condition -> WAV file");
    std::vector<std::string> names;
    for (auto it = st.begin(); it != st.end(); ++it)
      names.push_back(stimulus(it->second, p + ".stimuli." + it->first.Scalar(), it->first.Scalar(), page));
    return names;
  }

  std::string reference(const YAML::Node& n, const std::string& p, const std::string& page) {
    if (!n["reference"]) r_.fail(n, p, "missing 'reference' (the reference WAV file)");
    return stimulus(n["reference"], p + ".reference", "reference", page);
  }

  YAML::Node names(const std::vector<std::string>& list) {
    YAML::Node s = flow(YAML::Node(YAML::NodeType::Sequence));
    for (const std::string& x : list) s.push_back(x);
    return s;
  }

  void mushra(const YAML::Node& n, const std::string& p) {
    const std::string id = page_id(n, p, "mushra");
    YAML::Node b = block("mushra", id);
    const std::string ref = reference(n, p, id);
    b["reference"] = ref;
    b["conditions"] = names(conditions(n, p, id));
    const bool a35 = is_true(n["createAnchor35"]), a70 = is_true(n["createAnchor70"]);
    if (a35 && a70) b["anchors"] = "auto";
    else if (!a35 && !a70) b["anchors"] = "none";
    else b["anchors"] = names({lowpassed(ref, a35 ? 3500 : 7000)});
    if (n["randomize"] && !is_true(n["randomize"])) b["randomize"] = false;
    if (is_true(n["showConditionNames"]))
      note(n["showConditionNames"], p + ".showConditionNames", "not carried over: conditions stay blind (letters)");
    if (is_true(n["switchBack"]))
      note(n["switchBack"], p + ".switchBack", "not carried over: switching keeps the playing position");
    if (n["strict"] && !is_true(n["strict"]))
      note(n["strict"], p + ".strict", "not carried over: the protocol is always checked against BS.1534");
    prompt(b, n, p);
    blocks_.push_back(b);
  }

  // webMUSHRA's anchor: the reference low-passed at `hz`, a derived stimulus named REF_lpHZ.
  std::string lowpassed(const std::string& ref, int hz) {
    const std::string anchor = ref + "_lp" + std::to_string(hz);
    YAML::Node s;
    s["derive"] = ref;
    s["lowpass_hz"] = hz;
    stimuli_[anchor] = flow(s);
    return anchor;
  }

  // BS.1116: each condition (and each anchor webMUSHRA would create, as a low-passed reference)
  // against the open and the hidden reference.
  void bs1116(const YAML::Node& n, const std::string& p) {
    const std::string id = page_id(n, p, "bs1116");
    YAML::Node b = block("bs1116", id);
    const std::string ref = reference(n, p, id);
    b["reference"] = ref;
    std::vector<std::string> graded = conditions(n, p, id);
    for (const auto& [key, hz] : {std::pair{"createAnchor35", 3500}, {"createAnchor70", 7000}})
      if (is_true(n[key])) graded.push_back(lowpassed(ref, hz));
    b["conditions"] = names(graded);
    prompt(b, n, p);
    blocks_.push_back(b);
  }

  void prompt(YAML::Node& b, const YAML::Node& n, const std::string& p) {
    const std::string text = content(n, p);
    if (!text.empty()) b["prompt"] = text;
  }

  void paired(const YAML::Node& n, const std::string& p) {
    const std::string id = page_id(n, p, "paired_comparison");
    YAML::Node b = block("ab", id);
    b["mode"] = "preference";
    const std::string ref = reference(n, p, id);
    YAML::Node pairs(YAML::NodeType::Sequence);
    for (const std::string& c : conditions(n, p, id)) pairs.push_back(names({ref, c}));
    b["pairs"] = pairs;
    if (n["unforced"] && !n["unforced"].IsNull())
      note(n["unforced"], p + ".unforced", "not carried over: the answer is a forced choice between A and B");
    prompt(b, n, p);
    blocks_.push_back(b);
  }

  void likert(const YAML::Node& n, const std::string& p, const std::string& type) {
    const std::string id = page_id(n, p, type);
    YAML::Node b = block("rating", id);
    b["stimuli"] = names(conditions(n, p, id));
    const YAML::Node resp = n["response"];
    if (!resp || !resp.IsSequence() || resp.size() < 2)
      r_.fail(resp ? resp : n, p + ".response", "expected a list of at least two Likert points {value, label}");
    const auto label = [&](std::size_t i) {
      const YAML::Node point = resp[i];
      const std::string at = p + ".response[" + std::to_string(i) + "]";
      if (!point.IsMap() || (!point["label"] && !point["value"])) r_.fail(point, at, "expected a Likert point {value, label}");
      return r_.text(point["label"] ? point["label"] : point["value"], at + (point["label"] ? ".label" : ".value"));
    };
    YAML::Node attribute;
    attribute["name"] = id;
    attribute["points"] = resp.size();
    attribute["low"] = label(0);
    attribute["high"] = label(resp.size() - 1);
    b["attributes"].push_back(attribute);
    if (resp.size() > 2)
      note(resp, p + ".response", "the inner labels are not shown: answers are points 1.." + std::to_string(resp.size()) +
                                      " between '" + label(0) + "' and '" + label(resp.size() - 1) + "'");
    if (type == "likert_multi_stimulus")
      note(n["type"], p + ".type", "likert_multi_stimulus: the stimuli are rated one per trial, not side by side");
    if (n["maxStimuli"]) note(n["maxStimuli"], p + ".maxStimuli", "not carried over: every stimulus is rated");
    prompt(b, n, p);
    blocks_.push_back(b);
  }

  void finish(const YAML::Node& n, const std::string& p) {
    if (is_true(n["showResults"]))
      note(n["showResults"], p + ".showResults", "not carried over: participants do not see their results");
    const YAML::Node qs = n["questionnaire"];
    if (!qs || qs.IsNull()) return;
    if (!qs.IsSequence()) r_.fail(qs, p + ".questionnaire", "expected a list of questions {type, name, label}");
    YAML::Node b = block("questionnaire", page_id(n, p, "finish"));
    for (std::size_t i = 0; i < qs.size(); ++i) {
      const std::string qp = p + ".questionnaire[" + std::to_string(i) + "]";
      const YAML::Node item = qs[i];
      if (!item.IsMap() || !item["type"]) r_.fail(item, qp, "expected a question {type, name, label}");
      const std::string type = r_.text(item["type"], qp + ".type");
      YAML::Node q;
      q["id"] = as_id(item["name"] ? r_.text(item["name"], qp + ".name") : "", "q" + std::to_string(i + 1));
      q["text"] = item["label"] ? r_.text(item["label"], qp + ".label") : q["id"].as<std::string>();
      if (type == "likert") {
        const YAML::Node resp = item["response"];
        if (!resp || !resp.IsSequence() || resp.size() == 0) r_.fail(item, qp + ".response", "expected a list of {value, label}");
        YAML::Node options = flow(YAML::Node(YAML::NodeType::Sequence));
        for (std::size_t k = 0; k < resp.size(); ++k) {
          const std::string at = qp + ".response[" + std::to_string(k) + "]";
          if (!resp[k].IsMap() || !resp[k]["value"]) r_.fail(resp[k], at, "expected a Likert point {value, label}");
          options.push_back(r_.text(resp[k]["value"], at + ".value"));
        }
        q["options"] = options;
      } else if (type == "number") {
        note(item["type"], qp + ".type", "a number question is asked as free text (no range check)");
      } else if (type != "text" && type != "long_text") {
        r_.fail(item["type"], qp + ".type", "unknown question type '" + type + "' (text, long_text, number or likert)");
      }
      b["questions"].push_back(q);
    }
    blocks_.push_back(b);
  }

  YamlReader r_;
  std::string protocol_path_;
  fs::path config_dir_, root_, protocol_dir_;
  YAML::Node out_, stimuli_{YAML::NodeType::Map}, blocks_{YAML::NodeType::Sequence};
  int random_groups_ = 0;
  std::map<std::string, fs::path> files_;  // stimulus name -> the file it plays
  std::map<fs::path, double> rates_hz_;    // file -> its sample rate
  std::set<std::string> block_ids_;
  std::vector<std::string> notes_;
  double sample_rate_hz_ = 0;
  bool allow_outside_ = false;
};

}  // namespace

WebMushraImport import_webmushra(const std::string& config_path, const std::string& protocol_path) {
  return Importer(config_path, protocol_path).run(read_bounded_file(config_path, kYamlFileLimit));
}

}  // namespace ms
