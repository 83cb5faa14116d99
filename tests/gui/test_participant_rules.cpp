// The rules that keep a naive participant's answers honest, checked through the real views with QTest:
// no answer before every sound was heard (every block type), heard marks on the buttons, MUSHRA sliders
// that must be moved, the playing highlight following the mixer, keyboard moves in adjust playing the
// new sound, the magnitude field (decimal comma, refusals, 0 with identical pairs, focus), number and
// letter keys, training feedback, the staircase's progress, the resume notice and the experimenter lock.
#include <QCheckBox>
#include <QLabel>
#include <QRadioButton>

#include <algorithm>
#include <fstream>

#include "gui_fixture.hpp"
#include "studyapp/core/results_store.hpp"

using namespace gui_test;

namespace {

// A protocol over the demo's parameter sets (absolute paths) with the given blocks.
std::string write_protocol(const std::string& dir, const std::string& blocks) {
  const std::string stimuli = std::string(MODALSTUDY_SOURCE_DIR) + "/stimuli/";
  std::ofstream out(dir + "/p.yaml");
  out << "study: rules\nseed: 3\nstimuli:\n"
      << "  metal: {paramset: " << stimuli << "bar/sterling-steel.yaml}\n"
      << "  glass: {paramset: " << stimuli << "plate/sterling-glass.yaml}\n"
      << "  metal-rayleigh: {paramset: " << stimuli << "bar/sterling-steel.yaml, "
      << "set: {damping: {law: rayleigh, alpha1: 2.3, alpha2: 6.9e-8}}}\n"
      << "blocks:\n"
      << blocks;
  return dir + "/p.yaml";
}

ms::gui::AppOptions options_for(const std::string& protocol, const std::string& dir, const std::string& participant) {
  ms::gui::AppOptions o = demo_options(participant, dir + "/results.sqlite");
  o.protocol_path = protocol;
  o.allow_outside = true;
  return o;
}

// Runs until the window's mixer plays `index` (the null output renders every 10 ms).
bool mixer_plays(ms::gui::MainWindow& w, int index) {
  return wait_until([&] { return w.controller()->playing() && w.controller()->playing_index() == index; }, 2000);
}

QPushButton* next_of(ms::gui::MainWindow& w) { return w.trial_view()->findChild<QPushButton*>("next"); }
QString hint_of(ms::gui::MainWindow& w) { return w.trial_view()->findChild<QLabel*>("hint")->text(); }

}  // namespace

TEST(ParticipantRules, AbNextWaitsUntilBothSoundsWereHeardAndTheButtonsKeepAMark) {
  const std::string dir = fresh_dir("rules-ab");
  ms::gui::MainWindow w(options_for(write_protocol(dir, "  - {type: ab, pairs: [[metal, glass]]}\n"), dir, "R1"));
  ASSERT_TRUE(start_window(w));
  QWidget* v = w.trial_view();
  QTest::keyClick(v, Qt::Key_2);  // "Different"
  ASSERT_TRUE(child<QPushButton>(v, "choice-different")->isChecked());
  EXPECT_FALSE(next_of(w)->isEnabled());
  EXPECT_EQ(hint_of(w), "Listen to every sound before answering (0 of 2 heard).");
  auto* a = child<QPushButton>(v, "play-0");
  auto* b = child<QPushButton>(v, "play-1");
  EXPECT_FALSE(a->text().contains(QString::fromUtf8("\u2713")));
  QTest::mouseClick(a, Qt::LeftButton);
  EXPECT_FALSE(next_of(w)->isEnabled());
  EXPECT_EQ(hint_of(w), "Listen to every sound before answering (1 of 2 heard).");
  QTest::mouseClick(b, Qt::LeftButton);
  EXPECT_TRUE(next_of(w)->isEnabled());
  EXPECT_TRUE(hint_of(w).isEmpty());
  QTest::mouseClick(w.trial_view()->findChild<QPushButton*>("stop"), Qt::LeftButton);
  ASSERT_TRUE(wait_until([&] { return !w.controller()->playing(); }, 2000));
  QTest::qWait(30);
  EXPECT_TRUE(a->text().contains(QString::fromUtf8("\u2713"))) << a->text().toStdString();  // lasting mark
  EXPECT_TRUE(b->text().contains(QString::fromUtf8("\u2713"))) << b->text().toStdString();
}

TEST(ParticipantRules, ListenAllFalseLetsAnAnswerGoWithoutListening) {
  const std::string dir = fresh_dir("rules-listen-off");
  ms::gui::MainWindow w(options_for(
      write_protocol(dir, "  - {type: identify, stimuli: [metal], labels: [metal, glass], listen_all: false}\n"), dir, "R2"));
  ASSERT_TRUE(start_window(w));
  QTest::keyClick(w.trial_view(), Qt::Key_1);
  EXPECT_TRUE(next_of(w)->isEnabled());
}

TEST(ParticipantRules, PromptFromTheProtocolAndAParticipantFacingHeader) {
  const std::string dir = fresh_dir("rules-prompt");
  ms::gui::MainWindow w(options_for(
      write_protocol(dir, "  - {type: ab, id: abx-internal, mode: abx, prompt: \"Which of A and B is X?\", "
                          "pairs: [[metal, glass]]}\n"), dir, "R3"));
  ASSERT_TRUE(start_window(w));
  EXPECT_EQ(child<QLabel>(w.trial_view(), "prompt")->text(), "Which of A and B is X?");
  const QString header = w.findChild<QLabel*>("position")->text();
  EXPECT_TRUE(header.contains("Which one is X?")) << header.toStdString();
  EXPECT_FALSE(header.contains("abx")) << header.toStdString();
}

TEST(ParticipantRules, MushraNeedsEverySliderMovedAndTheHighlightFollowsTheMixer) {
  const std::string dir = fresh_dir("rules-mushra");
  ms::gui::MainWindow w(options_for(
      write_protocol(dir, "  - {type: mushra, reference: metal, conditions: [glass, metal-rayleigh], anchors: auto}\n"),
      dir, "R4"));
  ASSERT_TRUE(start_window(w));
  QWidget* v = w.trial_view();
  const auto sliders = children_with_prefix<QSlider>(v, "mushra-slider-");
  ASSERT_EQ(sliders.size(), 5u);  // hidden reference, 2 conditions, 2 anchors
  // Letters play the lettered sounds; the highlight follows the mixer after each switch.
  QTest::keyClick(v, Qt::Key_B);
  ASSERT_TRUE(mixer_plays(w, 2));
  QTest::qWait(30);
  EXPECT_TRUE(child<QPushButton>(v, "play-2")->isChecked());
  QTest::mouseClick(child<QPushButton>(v, "play-4"), Qt::LeftButton);  // D, while B plays: a switch
  ASSERT_TRUE(mixer_plays(w, 4));
  QTest::qWait(30);
  EXPECT_TRUE(child<QPushButton>(v, "play-4")->isChecked()) << "the mixer plays D; D must be lit";
  EXPECT_FALSE(child<QPushButton>(v, "play-2")->isChecked()) << "B is no longer playing";
  QTest::keyClick(v, Qt::Key_A);
  ASSERT_TRUE(mixer_plays(w, 1));
  QTest::qWait(30);
  EXPECT_TRUE(child<QPushButton>(v, "play-1")->isChecked());
  EXPECT_FALSE(child<QPushButton>(v, "play-4")->isChecked());
  {
    const auto events = w.controller()->session().store().event_rows();
    ASSERT_GE(events.size(), 3u);
    EXPECT_EQ(events.back().kind, "switch");
  }
  // Every sound heard, every slider still at its untouched 0: no answer yet.
  for (int i = 0; i < 6; ++i) QTest::mouseClick(child<QPushButton>(v, QString("play-%1").arg(i)), Qt::LeftButton);
  EXPECT_FALSE(next_of(w)->isEnabled());
  EXPECT_EQ(hint_of(w), "Rate every sound: move each slider at least once (5 are not rated yet).");
  for (std::size_t i = 0; i + 1 < sliders.size(); ++i) QTest::keyClick(sliders[i], Qt::Key_PageUp);
  EXPECT_FALSE(next_of(w)->isEnabled());
  QTest::keyClick(sliders.back(), Qt::Key_PageUp);
  EXPECT_TRUE(next_of(w)->isEnabled());
}

TEST(ParticipantRules, AdjustKeyboardMovesPlayTheNewSoundAndTheViewSpeaksToTheParticipant) {
  const std::string dir = fresh_dir("rules-adjust");
  ms::gui::MainWindow w(options_for(
      write_protocol(dir, "  - type: adjust\n    paramset: metal-rayleigh\n    target: metal\n"
                          "    prompt: \"Make the sound ring as long as the target.\"\n"
                          "    sliders:\n      - {key: damping.alpha1, min: 0.5, max: 10, label: Ringing, "
                          "low: long, high: short}\n"),
      dir, "R5"));
  ASSERT_TRUE(start_window(w));
  QWidget* v = w.trial_view();
  ASSERT_TRUE(wait_until([&] { return v->property("renders").toInt() >= 1; }));
  // Participant words only: the label and end labels, no key, no value, no timing.
  QStringList texts;
  for (auto* l : v->findChildren<QLabel*>()) texts << l->text();
  const QString all = texts.join("|");
  EXPECT_TRUE(all.contains("Ringing")) << all.toStdString();
  EXPECT_TRUE(all.contains("long") && all.contains("short")) << all.toStdString();
  EXPECT_FALSE(all.contains("damping")) << all.toStdString();
  EXPECT_FALSE(all.contains(" ms")) << all.toStdString();
  EXPECT_EQ(child<QLabel>(v, "prompt")->text(), "Make the sound ring as long as the target.");
  EXPECT_TRUE(v->findChildren<QLabel*>(QRegularExpression("^adjust-value-")).isEmpty());
  EXPECT_TRUE(child<QPushButton>(v, "play-0")->text().contains("Target"));
  EXPECT_FALSE(next_of(w)->isEnabled());  // neither the target nor the sound heard

  auto* slider = children_with_prefix<QSlider>(v, "adjust-")[0];
  const int before = v->property("renders").toInt();
  QTest::keyClick(slider, Qt::Key_Right);
  ASSERT_TRUE(wait_until([&] { return v->property("renders").toInt() > before; }));
  ASSERT_TRUE(wait_until([&] { return w.controller()->was_played(1); }, 2000)) << "a key move must play the new sound";
  const auto events = w.controller()->session().store().event_rows();
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.back().kind, "play");
  const auto detail = nlohmann::json::parse(events.back().detail_json);
  EXPECT_NEAR(detail["set"]["damping.alpha1"].get<double>(), 0.5 + 9.5 * (slider->value() / 100.0), 1e-9);
  EXPECT_TRUE(detail.contains("resynth_ms"));  // the timing goes to the log
  EXPECT_FALSE(next_of(w)->isEnabled());       // the target is not heard yet
  QTest::mouseClick(child<QPushButton>(v, "play-0"), Qt::LeftButton);
  EXPECT_TRUE(next_of(w)->isEnabled());
}

TEST(ParticipantRules, MagnitudeFieldTakesACommaSaysWhyAndHasTheFocus) {
  const std::string dir = fresh_dir("rules-magnitude");
  ms::gui::MainWindow w(options_for(
      write_protocol(dir, "  - {type: magnitude, modulus: [metal, glass], pairs: [[metal, glass]]}\n"
                          "  - {type: magnitude, modulus: [metal, glass], pairs: all_with_identical, stimuli: [metal, glass]}\n"),
      dir, "R6"));
  ASSERT_TRUE(start_window(w));
  QWidget* v = w.trial_view();
  auto* entry = child<QLineEdit>(v, "magnitude");
  ASSERT_TRUE(wait_until([&] { return entry->hasFocus(); }, 2000)) << "the field has the focus when the trial starts";
  EXPECT_TRUE(child<QPushButton>(v, "play-0")->text().contains("Reference pair"));
  for (int i = 0; i < 4; ++i) QTest::mouseClick(child<QPushButton>(v, QString("play-%1").arg(i)), Qt::LeftButton);
  QTest::keyClicks(entry, "0");
  EXPECT_FALSE(next_of(w)->isEnabled());
  EXPECT_EQ(hint_of(w), "Type a number above 0: every pair here differs at least a little.");
  entry->clear();
  QTest::keyClicks(entry, "abc");
  EXPECT_TRUE(hint_of(w).contains("is not a number")) << hint_of(w).toStdString();
  entry->clear();
  QTest::keyClicks(entry, "12,5");
  EXPECT_TRUE(next_of(w)->isEnabled());
  const std::size_t index = w.controller()->session().current_index();
  QTest::keyClick(entry, Qt::Key_Return);
  ASSERT_NE(w.controller()->session().current_index(), index);
  {
    const auto rows = w.controller()->session().store().response_rows();
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(nlohmann::json::parse(rows[0].value_json).get<double>(), 12.5);
  }
  // The identical pair: 0 is an answer.
  v = w.trial_view();
  entry = child<QLineEdit>(v, "magnitude");
  for (int i = 0; i < 4; ++i) QTest::mouseClick(child<QPushButton>(v, QString("play-%1").arg(i)), Qt::LeftButton);
  QTest::keyClicks(entry, "0");
  EXPECT_TRUE(next_of(w)->isEnabled()) << hint_of(w).toStdString();
}

TEST(ParticipantRules, BipolarNumberKeysAndTrainingFeedback) {
  const std::string dir = fresh_dir("rules-keys");
  ms::gui::MainWindow w(options_for(
      write_protocol(dir, "  - {type: ab, training: true, feedback: true, pairs: [[metal, glass]], randomize: false}\n"
                          "  - {type: ab, mode: bipolar, pairs: [[metal, glass]]}\n"),
      dir, "R7"));
  ASSERT_TRUE(start_window(w));
  QWidget* v = w.trial_view();
  for (int i = 0; i < 2; ++i) QTest::mouseClick(child<QPushButton>(v, QString("play-%1").arg(i)), Qt::LeftButton);
  QTest::keyClick(v, Qt::Key_1);  // "Same": wrong, metal and glass differ
  QTest::keyClick(v, Qt::Key_Return);
  auto* feedback = child<QLabel>(v, "feedback");
  EXPECT_TRUE(feedback->isVisible());
  EXPECT_EQ(feedback->text(), "Not quite: A and B were different sounds.");
  EXPECT_EQ(w.controller()->session().answered(), 0u);  // the answer waits for Continue
  EXPECT_TRUE(next_of(w)->text().startsWith("Continue"));
  QTest::keyClick(v, Qt::Key_Return);
  ASSERT_EQ(w.controller()->session().answered(), 1u);

  v = w.trial_view();
  for (int i = 0; i < 2; ++i) QTest::mouseClick(child<QPushButton>(v, QString("play-%1").arg(i)), Qt::LeftButton);
  QTest::keyClick(v, Qt::Key_6);  // the sixth point: +2
  EXPECT_TRUE(child<QRadioButton>(v, "bipolar-2")->isChecked());
  QTest::keyClick(v, Qt::Key_1);
  EXPECT_TRUE(child<QRadioButton>(v, "bipolar--3")->isChecked());
  EXPECT_TRUE(next_of(w)->isEnabled());
}

TEST(ParticipantRules, StaircaseShowsItsProgressAndItsButtonIsNext) {
  const std::string dir = fresh_dir("rules-staircase");
  ms::gui::MainWindow w(options_for(
      write_protocol(dir, "  - {type: staircase, stimulus: metal, parameter: duration_s, start: 0.6, step: 0.2, "
                          "reversals: 3}\n"),
      dir, "R8"));
  ASSERT_TRUE(start_window(w));
  QWidget* v = w.trial_view();
  EXPECT_TRUE(next_of(w)->text().startsWith("Next"));
  EXPECT_EQ(child<QLabel>(v, "step")->text().toStdString(),
            "Step 1 of at most 80 \u00B7 0 of 3 turning points \u2014 this part ends after 3 turning points.");
  auto* play0 = child<QPushButton>(v, "play-0");
  ASSERT_TRUE(wait_until([&] { return play0->isEnabled(); }));
  for (int i = 0; i < 3; ++i) QTest::mouseClick(child<QPushButton>(v, QString("play-%1").arg(i)), Qt::LeftButton);
  QTest::mouseClick(child<QPushButton>(v, "choice-A"), Qt::LeftButton);
  QTest::mouseClick(next_of(w), Qt::LeftButton);
  EXPECT_TRUE(child<QLabel>(v, "step")->text().startsWith("Step 2 of at most 80"));
}

// The view plays the comparison where the session's draw put it and reports the button pressed; the
// session scores it and stores the interval chosen.
TEST(ParticipantRules, StaircaseViewReportsTheButtonAndTheSessionScoresIt) {
  const std::string dir = fresh_dir("rules-staircase-choice");
  ms::gui::MainWindow w(options_for(
      write_protocol(dir, "  - {type: staircase, stimulus: metal, parameter: duration_s, start: 0.6, step: 0.2, "
                          "reversals: 3}\n"),
      dir, "R11"));
  ASSERT_TRUE(start_window(w));
  ms::Session& session = w.controller()->session();
  for (const bool right : {true, false}) {
    QWidget* v = w.trial_view();
    ASSERT_TRUE(wait_until([&] { return child<QPushButton>(v, "play-0")->isEnabled(); }));
    const ms::AbInterval comparison = session.staircase_comparison();
    const std::size_t in = comparison == ms::AbInterval::a ? 1 : 2;  // sounds: reference, A, B
    EXPECT_NE(w.controller()->sounds()[in].name.find('@'), std::string::npos) << w.controller()->sounds()[in].name;
    EXPECT_EQ(w.controller()->sounds()[3 - in].name.find('@'), std::string::npos);
    for (int i = 0; i < 3; ++i) QTest::mouseClick(child<QPushButton>(v, QString("play-%1").arg(i)), Qt::LeftButton);
    const ms::AbInterval chosen = right ? ms::other(comparison) : comparison;
    QTest::mouseClick(child<QPushButton>(v, QString::fromStdString("choice-" + to_string(chosen))), Qt::LeftButton);
    QTest::mouseClick(next_of(w), Qt::LeftButton);
    const auto events = session.store().event_rows();
    const auto step = std::find_if(events.rbegin(), events.rend(), [](const auto& e) { return e.kind == "step"; });
    ASSERT_NE(step, events.rend());
    const auto d = nlohmann::json::parse(step->detail_json);
    EXPECT_EQ(d["chosen"], to_string(chosen));
    EXPECT_EQ(d["comparison"], to_string(comparison));
    EXPECT_EQ(d["correct"], right);
  }
}

TEST(ParticipantRules, ResumeNoticeIsGoneAfterTheFirstTrial) {
  const std::string dir = fresh_dir("rules-resume");
  const std::string protocol = write_protocol(dir, "  - {type: instructions, text: one}\n  - {type: instructions, text: two}\n"
                                                   "  - {type: instructions, text: three}\n");
  {
    ms::gui::MainWindow w(options_for(protocol, dir, "R9"));
    ASSERT_TRUE(start_window(w));
    QTest::keyClick(w.trial_view(), Qt::Key_Return);
    ASSERT_EQ(w.controller()->session().answered(), 1u);
  }
  ms::gui::MainWindow w(options_for(protocol, dir, "R9"));
  ASSERT_TRUE(start_window(w));
  auto* notice = w.findChild<QLabel*>("resumedNotice");
  EXPECT_TRUE(notice->isVisible());
  QTest::keyClick(w.trial_view(), Qt::Key_Return);
  EXPECT_FALSE(notice->isVisible());
}

TEST(ParticipantRules, ExperimenterViewIsLockedDuringASession) {
  const std::string dir = fresh_dir("rules-lock");
  ms::gui::MainWindow w(options_for(write_protocol(dir, "  - {type: instructions, text: one}\n"), dir, "R10"));
  auto* action = w.findChild<QAction*>("experimenterAction");
  ASSERT_NE(action, nullptr);
  w.show();
  EXPECT_TRUE(action->isEnabled());  // the start page: the experimenter's own screen
  ASSERT_TRUE(start_window(w));
  EXPECT_FALSE(action->isEnabled());
  int asked = 0;
  w.set_experimenter_confirmation([&] { ++asked; return false; });
  EXPECT_EQ(w.request_experimenter_view(), nullptr);
  EXPECT_EQ(asked, 1);
  w.set_experimenter_confirmation([&] { ++asked; return true; });
  QWidget* opened = w.request_experimenter_view();
  ASSERT_NE(opened, nullptr);
  EXPECT_EQ(asked, 2);
  opened->close();
}

TEST(ParticipantRules, StartPageSaysWhatTheResultsFileHoldsForTheParticipant) {
  const std::string dir = fresh_dir("rules-status");
  const std::string protocol = write_protocol(dir, "  - {type: instructions, text: one}\n  - {type: instructions, text: two}\n");
  auto start_of = [](ms::gui::MainWindow& w) { return w.start_page().findChild<QPushButton*>("start"); };
  auto status_of = [](ms::gui::MainWindow& w) { return w.start_page().findChild<QLabel*>("participantStatus")->text(); };
  {
    ms::gui::MainWindow w(options_for(protocol, dir, "P07"));
    EXPECT_TRUE(status_of(w).isEmpty()) << status_of(w).toStdString();  // nothing stored yet
    ASSERT_TRUE(start_window(w));
    QTest::keyClick(w.trial_view(), Qt::Key_Return);  // 1 of 2 answered
  }
  {
    ms::gui::MainWindow w(options_for(protocol, dir, "P07"));
    EXPECT_TRUE(status_of(w).contains("has an unfinished session (1/2 trials answered)")) << status_of(w).toStdString();
    EXPECT_TRUE(status_of(w).contains("Start resumes it")) << status_of(w).toStdString();
    ASSERT_TRUE(start_window(w));
    QTest::keyClick(w.trial_view(), Qt::Key_Return);
    ASSERT_TRUE(w.controller()->session().finished());
  }
  ms::gui::MainWindow w(options_for(protocol, dir, "P07 "));
  w.show();
  const QString line = status_of(w);
  EXPECT_TRUE(line.contains("finished this study")) << line.toStdString();
  ASSERT_TRUE(wait_until([&] { return w.controller()->is_prepared(); }));
  QTest::qWait(20);
  EXPECT_FALSE(start_of(w)->isEnabled()) << "a finished participant starts only as a new session";
  auto* again = w.start_page().findChild<QCheckBox*>("newSession");
  ASSERT_TRUE(again->isVisibleTo(&w));
  again->setChecked(true);
  EXPECT_TRUE(start_of(w)->isEnabled());
  auto* participant = w.start_page().findChild<QLineEdit*>("participant");
  participant->setText("p07");
  EXPECT_FALSE(status_of(w).contains("finished")) << status_of(w).toStdString();
  EXPECT_TRUE(status_of(w).contains("Careful: 'P07' is already in this results file")) << status_of(w).toStdString();
  EXPECT_TRUE(start_of(w)->isEnabled());
}

TEST(ParticipantRules, MagnitudePromptAndFieldShowTheProtocolsModulusValue) {
  const std::string dir = fresh_dir("rules-modulus-value");
  ms::gui::MainWindow w(options_for(
      write_protocol(dir, "  - {type: magnitude, modulus: [metal, glass], modulus_value: 10, pairs: [[metal, glass]]}\n"),
      dir, "R9"));
  ASSERT_TRUE(start_window(w));
  QWidget* v = w.trial_view();
  const QString prompt = child<QLabel>(v, "prompt")->text();
  EXPECT_TRUE(prompt.contains("counts as 10.")) << prompt.toStdString();
  EXPECT_TRUE(prompt.contains("5 = half as different, 20 = twice")) << prompt.toStdString();
  EXPECT_FALSE(prompt.contains("100")) << prompt.toStdString();
  EXPECT_EQ(child<QLineEdit>(v, "magnitude")->placeholderText(), "how different? (reference pair = 10)");
}
