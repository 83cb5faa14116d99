// Questionnaire: a free-text line per open question, radio buttons per question with options. Next waits
// until every question with options is answered (free text may stay empty).
#include <QFormLayout>
#include <QLineEdit>
#include <QRadioButton>

#include "studyapp/core/answers.hpp"
#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class QuestionnaireView : public TrialView {
 public:
  QuestionnaireView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const auto* spec = std::get_if<QuestionnaireBlock>(&c.block().body);
    add_prompt("A few questions to finish.");
    auto* form = new QFormLayout;
    const std::vector<Question> questions = spec ? spec->questions : std::vector<Question>{};
    for (std::size_t i = 0; i < questions.size(); ++i) {
      const Question& q = questions[i];
      const std::string id = question_id(q, i);
      Item item{id, nullptr, nullptr, {}};
      if (q.options.empty()) {
        item.text = new QLineEdit(body());
        item.text->setObjectName(QString::fromStdString("question-" + id));
        form->addRow(QString::fromStdString(q.text), item.text);
      } else {
        auto* row = new QHBoxLayout;
        item.options = new QButtonGroup(this);
        for (std::size_t k = 0; k < q.options.size(); ++k) {
          auto* r = new QRadioButton(QString::fromStdString(q.options[k]), body());
          r->setObjectName(QString::fromStdString("option-" + id + "-" + q.options[k]));
          item.options->addButton(r, static_cast<int>(k));
          row->addWidget(r);
        }
        row->addStretch();
        item.option_texts = q.options;
        connect(item.options, &QButtonGroup::idClicked, this, [this] { refresh(); });
        form->addRow(QString::fromStdString(q.text), row);
      }
      items_.push_back(item);
    }
    layout_->addLayout(form);
    add_next([this] {
      QuestionnaireAnswer a;
      for (const Item& it : items_)
        a.answers[it.id] = it.text ? it.text->text().toStdString()
                                   : it.option_texts[static_cast<std::size_t>(it.options->checkedId())];
      return a;
    });
  }

 protected:
  bool ready() const override {
    for (const Item& it : items_)
      if (it.options && it.options->checkedId() < 0) return false;
    return true;
  }

 private:
  struct Item {
    std::string id;
    QLineEdit* text;
    QButtonGroup* options;
    std::vector<std::string> option_texts;
  };
  std::vector<Item> items_;
};

}  // namespace

TrialView* make_questionnaire_view(StudyController& c, QWidget* parent) { return new QuestionnaireView(c, parent); }

}  // namespace ms::gui
