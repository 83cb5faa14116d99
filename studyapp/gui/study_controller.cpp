// StudyController: protocol + stimulus cache + session + audio, and the per-trial play/answer state.
#include "studyapp/gui/study_controller.hpp"

#include <QThread>
#include <QThreadPool>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "studyapp/core/protocol_validator.hpp"
#include "synthesis/input_error.hpp"

namespace ms::gui {

StudyController::StudyController(const std::string& protocol_path, bool allow_outside, std::string cache_dir,
                                 QObject* parent)
    : QObject(parent), protocol_path_(protocol_path), cache_dir_(std::move(cache_dir)) {
  ValidateOptions validate;
  validate.allow_outside = allow_outside;
  ProtocolCheck check = check_protocol_file(protocol_path, validate);
  problems_ = std::move(check.problems);
  if (!check.protocol) {
    if (problems_.empty()) problems_.push_back(protocol_path + ": cannot be read");
    return;
  }
  if (!problems_.empty()) return;
  protocol_ = std::move(check.protocol);
  std::ifstream in(protocol_path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  protocol_text_ = text.str();
  try {
    cache_ = std::make_unique<StimulusCache>(*protocol_, cache_dir_);
  } catch (const InputError& e) {
    problems_.push_back(e.what());
    return;
  }
  set_audio_device("null");
  connect(this, &StudyController::prepared, this, [this](const QString& why) { prepared_ = why.isEmpty(); });
}

StudyController::~StudyController() {
  if (worker_) worker_->wait();
  QThreadPool::globalInstance()->waitForDone();  // adjust/staircase renders use the cache
  audio_.reset();
}

std::int64_t StudyController::now_ms() const { return unix_now_ms(); }

void StudyController::prepare() {
  if (worker_ || !cache_) return;
  worker_.reset(QThread::create([this] {
    try {
      cache_->prepare_all([this](std::size_t done, std::size_t total, const std::string& name) {
        emit prepareProgress(static_cast<int>(done), static_cast<int>(total), QString::fromStdString(name));
      });
      emit prepared(QString());
    } catch (const std::exception& e) {
      emit prepared(QString::fromStdString(e.what()));
    }
  }));
  worker_->start();
}

QString StudyController::set_audio_device(const QString& device) {
  audio_.reset();  // one sink at a time
  audio_ = std::make_unique<AudioOutput>(protocol_->sample_rate_hz, device);
  connect(audio_.get(), &AudioOutput::playingChanged, this, &StudyController::playingChanged);
  return audio_->message();
}

void StudyController::play_calibration_tone() {
  audio_->mixer().set_stimuli({calibration_tone(protocol_->sample_rate_hz)});
  audio_->mixer().play(0);
}

void StudyController::start_session(const std::string& participant, const std::string& db_path,
                                    const SessionStart& start) {
  preview_.reset();
  session_ = std::make_unique<Session>(*protocol_, protocol_text_, participant, db_path, cache_->hashes(), now_ms(), start);
  show_current();
}

const Trial& StudyController::trial() const { return preview_ ? *preview_ : session_->current(); }

const Block& StudyController::block() const { return protocol_->blocks.at(trial().block); }

void StudyController::preview(const Trial& trial) {
  preview_ = trial;
  audio_->mixer().stop();
  sounds_.clear();
  played_.clear();
}

Samples StudyController::samples(const std::string& stimulus) {
  if (preview_) return std::make_shared<const std::vector<float>>();
  return cache_->samples(stimulus);
}

void StudyController::hold_reaction_time() {
  if (!held_rt_ms_) held_rt_ms_ = elapsed_ms();
}

void StudyController::show_current() {
  audio_->mixer().stop();
  sounds_.clear();
  played_.clear();
  plays_ = 0;
  held_rt_ms_.reset();
  trial_clock_.start();
  if (session_->finished()) emit finished();
  else emit trialShown();
}

void StudyController::set_sounds(std::vector<Sound> sounds) {
  sounds_ = std::move(sounds);
  std::vector<Samples> buffers;
  for (const Sound& s : sounds_) buffers.push_back(s.samples);
  audio_->mixer().set_stimuli(std::move(buffers));
  played_.clear();
}

void StudyController::replace_sound(std::size_t index, Sound sound) {
  sounds_.at(index) = std::move(sound);
  const bool was_playing = playing();
  std::vector<Samples> buffers;
  for (const Sound& s : sounds_) buffers.push_back(s.samples);
  audio_->mixer().set_stimuli(std::move(buffers));  // stops playback
  played_.erase(index);  // the new version has not been heard
  if (was_playing) emit playingChanged(false);
}

void StudyController::set_loop(bool loop) { audio_->mixer().set_loop(loop); }

void StudyController::play(std::size_t index) {
  if (index >= sounds_.size() || !has_session()) return;
  audio_->mixer().play(index);
  session_->log_event(EventKind::play, sounds_[index].name, now_ms(), sounds_[index].detail_json);
  played_.insert(index);
  ++plays_;
  emit soundPlayed(static_cast<int>(index));
}

void StudyController::switch_to(std::size_t index) {
  if (index >= sounds_.size() || !has_session()) return;
  if (!playing()) return play(index);
  audio_->mixer().switch_to(index);
  session_->log_event(EventKind::switch_to, sounds_[index].name, now_ms(), sounds_[index].detail_json);
  played_.insert(index);
  ++plays_;
  emit soundPlayed(static_cast<int>(index));
}

void StudyController::stop() {
  if (!has_session()) return audio_->mixer().stop();
  const int current = playing_index();
  audio_->mixer().stop();
  if (current >= 0) {
    const Sound& sound = sounds_[static_cast<std::size_t>(current)];
    session_->log_event(EventKind::stop, sound.name, now_ms(), sound.detail_json);
  }
}

bool StudyController::playing() const { return audio_ && audio_->mixer().playing(); }

int StudyController::playing_index() const {
  if (!playing()) return -1;
  const int current = audio_->mixer().current();
  return current >= 0 && static_cast<std::size_t>(current) < sounds_.size() ? current : -1;
}

double StudyController::elapsed_ms() const {
  return held_rt_ms_ ? *held_rt_ms_ : static_cast<double>(trial_clock_.nsecsElapsed()) * 1e-6;
}

bool StudyController::submit(const nlohmann::json& value) {
  try {
    audio_->mixer().stop();
    session_->answer(value, elapsed_ms(), plays_, now_ms());
  } catch (const std::exception& e) {
    emit error(QString::fromStdString(e.what()));
    return false;
  }
  if (!session_->finished() && session_->at_break()) {
    emit breakReached();
    return true;
  }
  show_current();
  return true;
}

StaircaseReply StudyController::staircase_step(AbInterval chosen) {
  const std::size_t trial = session_->current_index();
  StaircaseReply reply;
  try {
    reply.correct = session_->staircase_step(chosen, elapsed_ms(), now_ms());
  } catch (const std::exception& e) {
    emit error(QString::fromStdString(e.what()));
    reply.goes_on = true;
    return reply;
  }
  if (session_->current_index() == trial && !session_->finished()) {
    played_.clear();
    held_rt_ms_.reset();
    trial_clock_.start();
    reply.goes_on = true;
    return reply;
  }
  if (!session_->finished() && session_->at_break()) emit breakReached();
  else show_current();
  return reply;
}

bool StudyController::limits_step(bool different) {
  return series_step([&] { session_->limits_step(different, elapsed_ms(), now_ms()); });
}

bool StudyController::tokens_step(bool different) {
  return series_step([&] { session_->tokens_step(different, elapsed_ms(), now_ms()); });
}

// One step of a series run inside its trial: a new step starts unheard and untimed; the trial after
// the series' last step shows (or the break).
bool StudyController::series_step(const std::function<void()>& commit) {
  const std::size_t trial = session_->current_index();
  try {
    commit();
  } catch (const std::exception& e) {
    emit error(QString::fromStdString(e.what()));
    return true;
  }
  if (session_->current_index() == trial && !session_->finished()) {
    played_.clear();
    held_rt_ms_.reset();
    trial_clock_.start();
    return true;
  }
  if (!session_->finished() && session_->at_break()) emit breakReached();
  else show_current();
  return false;
}

void StudyController::continue_after_break() { show_current(); }

}  // namespace ms::gui
