#pragma once
// ResultScreen: the attempt's result. PASSED or NOT PASSED, the stars, the score and
// time with why it ended, the breakdown (measure, measured, points, of) and what to
// improve; a note when the records could not be written (the attempt waits in a
// pending file) or when the attempt became the stage's demonstration. Course, Retry,
// Debrief and Next stage (enabled once the next stage is unlocked); for a trainer (not
// in the kiosk) "Save as demonstration…" and "Use as this stage's demonstration" for
// an attempt whose input was recorded.

#include "ide/i18n/texts.h"

#include <QWidget>

class QLabel;
class QListWidget;
class QPushButton;
class QTableWidget;

namespace studio {

class TrainingController;

class ResultScreen : public QWidget {
    Q_OBJECT
public:
    explicit ResultScreen(TrainingController* training, QWidget* parent = nullptr);

    /// Shows the controller's last run (nothing before one). `kiosk`: no demonstration buttons.
    void fill(bool kiosk);
    /// Every text in the UI's language.
    void retranslate(bool kiosk);

    QLabel* heading() const { return m_heading; }
    QLabel* score() const { return m_score; }
    QLabel* note() const { return m_note; }
    QTableWidget* breakdown() const { return m_breakdown; }

signals:
    void courseRequested();
    void retryRequested();
    void debriefRequested();
    void nextRequested();

private:
    TrainingController* m_training;
    i18n::Texts m_texts;
    bool m_kiosk = false;
    QLabel* m_heading = nullptr;
    QLabel* m_stars = nullptr;
    QLabel* m_score = nullptr;
    QLabel* m_note = nullptr;
    QTableWidget* m_breakdown = nullptr;
    QListWidget* m_improvements = nullptr;
    QPushButton* m_nextButton = nullptr;
    QPushButton* m_saveDemoButton = nullptr;
    QPushButton* m_useDemoButton = nullptr;
};

}  // namespace studio
