// StudyService: per participant link a Session, the presentation last sent, and the requests on them.
#include "studyapp/web/study_service.hpp"

#include <filesystem>
#include <mutex>
#include <optional>

#include "studyapp/core/answer_gate.hpp"
#include "studyapp/core/session.hpp"
#include "studyapp/core/training_feedback.hpp"
#include "studyapp/web/browser_answer.hpp"
#include "studyapp/web/trial_presentation.hpp"
#include "studyapp/web/web_token.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/bounded_file.hpp"

namespace ms::web {

namespace fs = std::filesystem;

struct StudyService::Participant {
  ParticipantLink link;
  std::mutex mutex;                  // one request of a participant at a time
  std::unique_ptr<Session> session;  // open while the participant has trials left
  bool finished = false;
  std::optional<Presentation> shown; // the trial (and step) last sent
};

StudyService::StudyService(ServiceSetup setup) : setup_(std::move(setup)) {
  for (const ParticipantLink& link : setup_.links) {
    auto p = std::make_unique<Participant>();
    p->link = link;
    by_token_.emplace(link.token, std::move(p));
  }
}

StudyService::~StudyService() = default;

bool StudyService::knows(const std::string& token) const {
  return token_shaped(token) && by_token_.count(token) > 0;
}

StudyService::Participant& StudyService::find(const std::string& token) const {
  const auto it = token_shaped(token) ? by_token_.find(token) : by_token_.end();
  if (it == by_token_.end()) throw Refusal(404, "no such participant link");
  return *it->second;
}

void StudyService::open(Participant& p) {
  if (p.session || p.finished) return;
  try {
    p.session = std::make_unique<Session>(*setup_.protocol, setup_.protocol_text, p.link.participant, setup_.db_path,
                                          setup_.cache->hashes(), unix_now_ms());
  } catch (const ParticipantFinished&) {
    p.finished = true;
  } catch (const SessionInUse&) {
    throw Refusal(409, "this participant's session is open in another program");
  }
  if (p.session && p.session->finished()) {
    p.session.reset();
    p.finished = true;
  }
}

nlohmann::json StudyService::current_page(Participant& p) {
  open(p);
  if (p.session && p.session->finished()) {
    p.session.reset();  // the lease goes with it
    p.finished = true;
  }
  if (p.finished) return nlohmann::json{{"finished", true}};
  if (!p.shown) p.shown = present(*p.session, *setup_.cache);
  return p.shown->page;
}

WebResponse StudyService::trial(const std::string& token) {
  Participant& p = find(token);
  const std::lock_guard<std::mutex> lock(p.mutex);
  return json_response({{"title", setup_.protocol->title}, {"page", current_page(p)}});
}

namespace {

// The trial and step a request names must be those last sent: an earlier one was answered already
// (a replay), a later one was not sent yet.
void check_addressed(const nlohmann::json& body, const std::optional<Presentation>& shown, bool finished) {
  const std::size_t trial = index_field(body, "trial");
  const std::size_t step = body.contains("step") ? index_field(body, "step") : 0;
  if (finished) throw Refusal(409, "this session is finished: trial " + std::to_string(trial) + " was answered already");
  if (!shown) throw Refusal(409, "trial " + std::to_string(trial) + " has not been sent yet");
  if (trial < shown->trial || (trial == shown->trial && step < shown->step))
    throw Refusal(409, "trial " + std::to_string(trial) + " step " + std::to_string(step) + " was answered already");
  if (trial != shown->trial || step != shown->step)
    throw Refusal(409, "trial " + std::to_string(trial) + " step " + std::to_string(step) + " has not been sent yet");
}

}  // namespace

WebResponse StudyService::about_sent_trial(const std::string& token, const std::string& text,
                                           const std::function<WebResponse(Participant&, const nlohmann::json&)>& handle) {
  Participant& p = find(token);
  const nlohmann::json body = parse_json_body(text);
  const std::lock_guard<std::mutex> lock(p.mutex);
  open(p);
  check_addressed(body, p.shown, p.finished);
  return handle(p, body);
}

WebResponse StudyService::answer(const std::string& token, const std::string& text) {
  return about_sent_trial(token, text, [this](Participant& p, const nlohmann::json& body) {
    Session& session = *p.session;
    const Block& block = session.current_block();
    const Trial trial = session.current();
    const double rt_ms = number_field(body, "rt_ms", 0.0, 1e9);
    const nlohmann::json stored = stored_answer(block, *p.shown, field(body, "answer"));
    const nlohmann::json moved = body.contains("moved") ? body["moved"] : nlohmann::json::array();
    const AnswerGate gate = answer_gate(block, trial_inputs(block, trial, *p.shown, stored, moved));
    if (!gate.may_send) throw Refusal(422, gate.missing);
    nlohmann::json reply = nlohmann::json::object();
    try {
      if (block.type == BlockType::staircase) {
        const bool correct = session.staircase_step(stored == "B" ? AbInterval::b : AbInterval::a, rt_ms, unix_now_ms());
        if (block.feedback) reply["feedback"] = {{"correct", correct}, {"message", correct ? "Right." : "Not quite."}};
      } else if (block.type == BlockType::limits) {
        session.limits_step(stored == "different", rt_ms, unix_now_ms());
      } else if (block.type == BlockType::tokens) {
        session.tokens_step(stored == "different", rt_ms, unix_now_ms());
      } else {
        const auto feedback = block.feedback ? training_feedback(*setup_.protocol, block, trial, stored) : std::nullopt;
        session.answer(stored, rt_ms, p.shown->plays, unix_now_ms());
        if (feedback) reply["feedback"] = {{"correct", feedback->correct}, {"message", feedback->message}};
      }
    } catch (const std::invalid_argument& e) {
      throw Refusal(422, e.what());  // response_format refused it: nothing was stored
    }
    p.shown.reset();
    reply["break"] = !session.finished() && session.at_break();
    reply["page"] = current_page(p);
    return json_response(reply);
  });
}

WebResponse StudyService::event(const std::string& token, const std::string& text) {
  return about_sent_trial(token, text, [](Participant& p, const nlohmann::json& body) {
    const std::string kind_text = string_field(body, "kind", 16);
    const EventKind kind = kind_text == "play" ? EventKind::play
                           : kind_text == "stop" ? EventKind::stop
                           : kind_text == "switch" ? EventKind::switch_to
                                                   : throw Refusal(400, "request body: 'kind' must be play, stop or switch");
    const auto i = find_sound(*p.shown, string_field(body, "sound", 128));
    if (!i) throw Refusal(404, "no such sound in this trial");
    PresentedSound& sound = p.shown->sounds[*i];
    nlohmann::json detail = sound.detail_json.empty() ? nlohmann::json::object() : nlohmann::json::parse(sound.detail_json);
    if (body.contains("at_ms")) detail["client_ms"] = number_field(body, "at_ms", 0.0, 1e15);
    if (body.contains("position_s")) detail["position_s"] = number_field(body, "position_s", 0.0, 1e6);
    p.session->log_event(kind, sound.name, unix_now_ms(), detail.empty() ? "" : detail.dump());
    if (kind != EventKind::stop) {
      sound.heard = true;
      ++p.shown->plays;
    }
    return json_response({{"ok", true}});
  });
}

WebResponse StudyService::render(const std::string& token, const std::string& text) {
  return about_sent_trial(token, text, [this](Participant& p, const nlohmann::json& body) {
    const Block& block = p.session->current_block();
    if (block.type != BlockType::adjust) throw Refusal(409, "this trial makes no new sounds");
    const nlohmann::json& positions = field(body, "positions");
    std::vector<int> values;
    if (positions.is_array())
      for (const auto& v : positions) values.push_back(v.is_number_integer() ? v.get<int>() : -1);
    try {
      render_adjust_variant(*p.shown, block, *setup_.cache, values);
    } catch (const std::invalid_argument& e) {
      throw Refusal(400, std::string("request body: 'positions': ") + e.what());
    } catch (const InputError&) {
      throw Refusal(422, "This setting cannot be played; please move the slider a little.");
    }
    p.shown->page = page_json(*p.session, *p.shown, *setup_.cache);
    const PresentedSound& s = p.shown->sounds[p.shown->adjusted];
    return json_response({{"sound", {{"id", s.id}, {"label", s.label}}}, {"values", p.shown->adjusted_values}});
  });
}

WebResponse StudyService::sound(const std::string& token, const std::string& id) {
  Participant& p = find(token);
  const std::lock_guard<std::mutex> lock(p.mutex);
  const auto i = p.shown ? find_sound(*p.shown, id) : std::nullopt;
  if (!i) throw Refusal(404, "no such sound in this trial");
  const PresentedSound& s = p.shown->sounds[*i];
  // The cache's file, named by the hash the server computed (nothing of the request reaches the path).
  const std::string file = (fs::path(setup_.cache_dir) / (s.hash + ".wav")).string();
  if (std::error_code ec; !fs::is_regular_file(file, ec)) {
    const Samples samples = s.overrides.empty() ? setup_.cache->samples(s.stimulus)
                                                : setup_.cache->samples_with(s.stimulus, s.overrides);
    write_wav(file, Audio{setup_.cache->sample_rate_hz(), 1, *samples}, SampleFormat::float32);
  }
  WebResponse r;
  r.content_type = "audio/wav";
  r.body = read_bounded_file(file, kAudioFileLimit);
  return r;
}

}  // namespace ms::web
