// The one model the window is a view of: the loaded protocol, its rendered stimuli (StimulusCache), the
// participant's Session and the audio output. Views ask it to play sounds and commit answers; it logs
// every play/stop/switch, counts plays, times the reaction and tells the window what to show next.
#pragma once
#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studyapp/core/protocol.hpp"
#include "studyapp/core/session.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "studyapp/gui/audio_output.hpp"

namespace ms::gui {

// A sound a view can play: the name logged with its events and the samples.
struct Sound {
  std::string name;
  Samples samples;
  std::string detail_json = {};  // logged with its play/switch/stop events (e.g. an adjust variant's slider values)
};

// A staircase step as the session took it: was the choice right, and does the track go on in this trial.
struct StaircaseReply {
  bool correct = false;
  bool goes_on = false;
};

class StudyController : public QObject {
  Q_OBJECT

 public:
  // Loads and validates the protocol; on problems (every one, file:line:col) problems() is non-empty
  // and nothing else may be called except problems().
  StudyController(const std::string& protocol_path, bool allow_outside, std::string cache_dir,
                  QObject* parent = nullptr);
  ~StudyController() override;

  const std::vector<std::string>& problems() const { return problems_; }
  const Protocol& protocol() const { return *protocol_; }
  const std::string& protocol_path() const { return protocol_path_; }
  StimulusCache& cache() { return *cache_; }

  // Renders every stimulus in a worker thread: prepareProgress while it runs, then prepared("") or
  // prepared(reason).
  void prepare();
  bool is_prepared() const { return prepared_; }

  // Replaces the audio output (the calibration tone and trials then use it); returns its message.
  QString set_audio_device(const QString& device);
  AudioOutput& audio() { return *audio_; }
  void play_calibration_tone();

  // Opens or resumes the participant's session; emits trialShown (or finished). Throws InputError.
  void start_session(const std::string& participant, const std::string& db_path, const SessionStart& start = {});
  bool has_session() const { return session_ != nullptr; }
  Session& session() { return *session_; }

  // The trial a view shows and its block: the session's current one, or the previewed one.
  const Trial& trial() const;         // precondition: has_trial()
  const Block& block() const;
  bool has_trial() const { return preview_.has_value() || (session_ && !session_->finished()); }
  // Layout preview without a session (tests, screenshots of every block): views of `trial` can be built;
  // sounds are empty buffers, nothing is played, logged or stored.
  void preview(const Trial& trial);
  bool previewing() const { return preview_.has_value(); }
  Samples samples(const std::string& stimulus);  // the cache's, or an empty buffer in a preview

  // --- the current trial: sounds, plays, answer ---
  void set_sounds(std::vector<Sound> sounds);
  void replace_sound(std::size_t index, Sound sound);  // adjust/staircase: a re-synthesised version (not heard yet)
  const std::vector<Sound>& sounds() const { return sounds_; }
  void set_loop(bool loop);
  void play(std::size_t index);       // from the start; logs "play"; the sound counts as heard
  void switch_to(std::size_t index);  // same position if playing (MUSHRA); logs "switch"
  void stop();                        // logs "stop"
  bool playing() const;
  int playing_index() const;          // what the mixer plays now (-1 when silent); views light its button
  bool was_played(std::size_t index) const { return played_.count(index) > 0; }
  bool played_all() const { return played_.size() >= sounds_.size(); }
  int plays() const { return plays_; }
  double elapsed_ms() const;           // since the trial was shown (or until hold_reaction_time())
  void hold_reaction_time();           // the answer is given: training feedback time is not reaction time

  // Commits the answer (Session::answer) before anything else is shown; false (and error signal) if
  // the session rejects it.
  bool submit(const nlohmann::json& value);
  // Staircase: commits the interval chosen in one step (the session scores it).
  StaircaseReply staircase_step(AbInterval chosen);
  // Method of limits: commits one "same"/"different" of the series; true while the series goes on.
  bool limits_step(bool different);
  // Token series: commits one "same"/"different" comparison; true while the series goes on.
  bool tokens_step(bool different);
  void continue_after_break();        // from the break page

 signals:
  void prepareProgress(int done, int total, QString name);
  void prepared(QString error);
  void trialShown();                  // a new trial is current (show its view)
  void breakReached();
  void finished();
  void playingChanged(bool playing);
  void soundPlayed(int index);
  void error(QString message);

 private:
  void show_current();
  bool series_step(const std::function<void()>& commit);
  std::int64_t now_ms() const;

  std::string protocol_path_, protocol_text_, cache_dir_;
  std::vector<std::string> problems_;
  std::optional<Protocol> protocol_;
  std::unique_ptr<StimulusCache> cache_;
  std::unique_ptr<AudioOutput> audio_;
  std::unique_ptr<Session> session_;
  bool prepared_ = false;
  std::unique_ptr<class QThread> worker_;  // prepare(); joined on destruction

  std::optional<Trial> preview_;
  std::optional<double> held_rt_ms_;
  std::vector<Sound> sounds_;
  std::set<std::size_t> played_;
  int plays_ = 0;
  QElapsedTimer trial_clock_;
};

}  // namespace ms::gui
