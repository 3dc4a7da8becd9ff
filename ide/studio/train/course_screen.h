#pragma once
// CourseScreen: the Train workspace's first screen. The tutorials of the course
// (TrainingController) as a list: "Level n — title", the operator's best stars and
// score, locked stages and tutorials that cannot be used disabled with why as tooltip.
// Above it the languages, each in its own name and big enough for a finger on the
// kiosk's touch screen (i18n::switchTo: the whole application at once), and the
// operator (an editable list of the known ones); below it Records (the trainer's
// view), the training centre's indicator and Open.

#include "ide/i18n/texts.h"

#include <QList>
#include <QWidget>

class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;

namespace studio {

class TrainingController;

class CourseScreen : public QWidget {
    Q_OBJECT
public:
    explicit CourseScreen(TrainingController* training, QWidget* parent = nullptr);

    /// The list again: titles, progress and locks.
    void refresh();
    /// The operator box again: the known operators, the one in training chosen.
    void showOperators();
    /// Every text in the UI's language (the titles retitled by the controller before).
    void retranslate();

    QListWidget* courseList() const { return m_courseList; }
    QPushButton* recordsButton() const { return m_recordsButton; }
    QLabel* title() const { return m_title; }
    /// The training centre's indicator (TrainPage::setCentreLink fills it).
    QLabel* centreLabel() const { return m_centre; }
    /// The button that switches to language `code` ("es", "en"; nullptr: none).
    QPushButton* languageButton(const QString& code) const;

signals:
    void openRequested(const QString& tutorialId);
    void operatorChosen(const QString& id);
    void recordsRequested();

private:
    TrainingController* m_training;
    i18n::Texts m_texts;
    QLabel* m_title = nullptr;
    QList<QPushButton*> m_languageButtons;  ///< objectName "LanguageButton_<code>"
    QComboBox* m_operatorBox = nullptr;
    QListWidget* m_courseList = nullptr;
    QPushButton* m_recordsButton = nullptr;
    QLabel* m_centre = nullptr;
    QPushButton* m_openButton = nullptr;
};

}  // namespace studio
