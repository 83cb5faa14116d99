// Clipping check shared by the layout tests and the screenshots: every visible interactive widget (button,
// slider, line edit, combo box) lies fully inside each of its ancestors up to the window — or, inside a
// scroll area, fully inside the scrolled content (reachable by scrolling) with the scroll area itself
// inside the window — and is no narrower than its minimum size hint (no cut-off text).
#pragma once
#include <QAbstractButton>
#include <QComboBox>
#include <QLineEdit>
#include <QScrollArea>
#include <QSlider>
#include <QWidget>

#include <string>
#include <vector>

namespace gui_test {

inline std::string describe_widget(const QWidget* w) {
  const QString text = qobject_cast<const QAbstractButton*>(w) ? qobject_cast<const QAbstractButton*>(w)->text() : QString();
  return (w->objectName().isEmpty() ? std::string(w->metaObject()->className()) : w->objectName().toStdString()) +
         (text.isEmpty() ? "" : " '" + text.toStdString() + "'");
}

inline std::vector<std::string> clipped_widgets(QWidget& window) {
  std::vector<std::string> problems;
  for (QWidget* w : window.findChildren<QWidget*>()) {
    const bool interactive = qobject_cast<QAbstractButton*>(w) || qobject_cast<QSlider*>(w) ||
                             qobject_cast<QLineEdit*>(w) || qobject_cast<QComboBox*>(w);
    if (!interactive || !w->isVisibleTo(&window) || w->window() != &window) continue;
    if (qobject_cast<QScrollArea*>(w->parentWidget())) continue;  // a scroll bar's own buttons
    for (QWidget* a = w->parentWidget(); a; a = a->parentWidget()) {
      const QRect inside(w->mapTo(a, QPoint(0, 0)), w->size());
      auto* scroll = a->parentWidget() ? qobject_cast<QScrollArea*>(a->parentWidget()->parentWidget()) : nullptr;
      if (!a->rect().contains(inside)) {
        problems.push_back(describe_widget(w) + " is clipped by " + describe_widget(a));
        break;
      }
      if (scroll && scroll->widget() == a) {  // scrolled content: the scroll area must be in the window
        const QRect area(scroll->mapTo(&window, QPoint(0, 0)), scroll->size());
        if (!window.rect().contains(area)) problems.push_back("the scroll area around " + describe_widget(w) + " leaves the window");
        break;
      }
      if (a == &window) break;
    }
    if (qobject_cast<QAbstractButton*>(w) && w->width() < w->minimumSizeHint().width() && w->minimumWidth() == 0)
      problems.push_back(describe_widget(w) + " is narrower than its text");
  }
  return problems;
}

}  // namespace gui_test
