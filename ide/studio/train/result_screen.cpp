#include "ide/studio/train/result_screen.h"

#include "ide/studio/train/train_ui.h"
#include "ide/studio/train/training_controller.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace studio {

using trainui::num;

ResultScreen::ResultScreen(TrainingController* training, QWidget* parent) : QWidget(parent), m_training(training)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(32, 24, 32, 24);
    m_heading = new QLabel;
    m_heading->setObjectName("ResultHeading");
    m_heading->setAlignment(Qt::AlignCenter);
    m_stars = new QLabel;
    m_stars->setAlignment(Qt::AlignCenter);
    m_stars->setStyleSheet("font-size: 44px; color: #e6a700;");
    m_score = new QLabel;
    m_score->setObjectName("ResultScore");
    m_score->setAlignment(Qt::AlignCenter);
    m_score->setWordWrap(true);
    m_score->setStyleSheet("font-size: 20pt;");
    layout->addWidget(m_heading);
    layout->addWidget(m_stars);
    layout->addWidget(m_score);
    m_note = trainui::wrapped();
    m_note->setObjectName("ResultNote");
    m_note->setAlignment(Qt::AlignCenter);
    m_note->setStyleSheet("color: #b35c00;");
    layout->addWidget(m_note);
    auto* middle = new QHBoxLayout;
    m_breakdown = new QTableWidget(0, 4);
    m_breakdown->setObjectName("Breakdown");
    m_breakdown->verticalHeader()->hide();
    m_breakdown->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_breakdown->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_breakdown->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    m_breakdown->horizontalHeader()->setSectionResizeMode(3, QHeaderView::ResizeToContents);
    m_breakdown->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_breakdown->setSelectionMode(QAbstractItemView::NoSelection);
    auto* left = new QVBoxLayout;
    auto* scoreTitle = new QLabel;
    left->addWidget(scoreTitle);
    left->addWidget(m_breakdown);
    middle->addLayout(left, 1);
    auto* right = new QVBoxLayout;
    auto* improveTitle = new QLabel;
    right->addWidget(improveTitle);
    m_improvements = new QListWidget;
    m_improvements->setObjectName("Improvements");
    m_improvements->setWordWrap(true);
    m_improvements->setStyleSheet("QListWidget::item { padding: 6px 2px; }");
    right->addWidget(m_improvements);
    middle->addLayout(right, 1);
    layout->addLayout(middle, 1);
    auto* buttons = new QHBoxLayout;
    auto* course = new QPushButton;
    auto* retryButton = new QPushButton;
    retryButton->setObjectName("RetryButton");
    auto* debrief = new QPushButton;
    debrief->setObjectName("DebriefButton");
    m_nextButton = new QPushButton;
    m_nextButton->setObjectName("NextButton");
    buttons->addWidget(course);
    m_saveDemoButton = new QPushButton;
    m_saveDemoButton->setObjectName("SaveDemoButton");
    m_useDemoButton = new QPushButton;
    m_useDemoButton->setObjectName("UseDemoButton");
    m_texts.add([=, this] {
        m_breakdown->setHorizontalHeaderLabels({tr("Measure"), tr("Measured"), tr("Points"), tr("Of")});
        scoreTitle->setText("<b>" + tr("Score") + "</b>");
        improveTitle->setText("<b>" + tr("What to improve") + "</b>");
        course->setText(tr("Course"));
        retryButton->setText(tr("Retry"));
        debrief->setText(tr("Debrief"));
        m_nextButton->setText(tr("Next stage"));
        m_saveDemoButton->setText(tr("Save as demonstration…"));
        m_saveDemoButton->setToolTip(tr("Saves the operator's input of this attempt as an input log."));
        m_useDemoButton->setText(tr("Use as this stage's demonstration"));
        m_useDemoButton->setToolTip(tr("From now on the demonstration, the expert and the comparison of this stage "
                                       "replay this attempt's input instead of the shipped one."));
    });
    // the trainer's buttons on a row of their own: with the operator's, too wide in
    // Spanish for a 1280-pixel screen
    auto* trainerButtons = new QHBoxLayout;
    trainerButtons->addWidget(m_saveDemoButton);
    trainerButtons->addWidget(m_useDemoButton);
    trainerButtons->addStretch();
    connect(m_saveDemoButton, &QPushButton::clicked, this, [this] {
        const auto t = m_training->tutorial();
        if (!t) return;
        const QString path = QFileDialog::getSaveFileName(this, tr("Save as demonstration"),
                                                          TrainingController::userDemonstrationPath(
                                                              QString::fromStdString(t->spec.id)),
                                                          tr("Padrob input logs (*.log);;All files (*)"));
        QString error;
        if (!path.isEmpty() && !m_training->saveDemonstration(path, &error))
            QMessageBox::warning(this, tr("Save as demonstration"), error);
    });
    connect(m_useDemoButton, &QPushButton::clicked, this, [this] {
        QString error;
        if (m_training->useAsDemonstration({}, &error)) {
            m_training->setMadeDemonstration(true);
            fill(m_kiosk);
        } else {
            QMessageBox::warning(this, tr("Use as this stage's demonstration"), error);
        }
    });
    buttons->addStretch();
    buttons->addWidget(retryButton);
    buttons->addWidget(debrief);
    buttons->addWidget(m_nextButton);
    layout->addLayout(trainerButtons);
    layout->addLayout(buttons);
    connect(course, &QPushButton::clicked, this, &ResultScreen::courseRequested);
    connect(retryButton, &QPushButton::clicked, this, &ResultScreen::retryRequested);
    connect(debrief, &QPushButton::clicked, this, &ResultScreen::debriefRequested);
    connect(m_nextButton, &QPushButton::clicked, this, &ResultScreen::nextRequested);
}

void ResultScreen::retranslate(bool kiosk)
{
    m_texts.apply();
    fill(kiosk);
}

void ResultScreen::fill(bool kiosk)
{
    m_kiosk = kiosk;
    const trainer::RunOutput* run = m_training->lastRun();
    if (!run) return;
    const trainer::TutorialResult& r = run->result;
    m_heading->setText(r.passed ? tr("PASSED") : tr("NOT PASSED"));
    m_heading->setStyleSheet(
        QStringLiteral("font-size: 40px; font-weight: bold; color: %1;").arg(r.passed ? "#2e9d4a" : "#c0392b"));
    m_stars->setText(trainui::stars(r.stars));
    QString why;
    if (r.endReason == "time-up") why = tr("The time ran out.");
    else if (r.endReason == "hard-hit") why = tr("The machine hit the scene too hard.");
    else if (r.endReason == "worker-hit") why = tr("The machine touched a worker.");
    else if (r.endReason == "aborted") why = tr("The attempt was stopped.");
    else if (r.endReason == "input-ended") why = tr("The input ended before the goals were done.");
    else if (r.endReason == "solver-error") why = tr("The simulation failed.");
    QString score = tr("Score %1 of 100 in %2 s").arg(num(r.score, 0), num(r.time, 1));
    // unfinished: how much of the stage was done (what path, smoothness and safety were earned on)
    if (!r.completed) score += QLatin1Char('\n') + tr("Work done: %1 % of the stage").arg(num(100.0 * r.work, 0));
    m_score->setText(why.isEmpty() ? score : score + QLatin1Char('\n') + why);
    QString note;
    if (m_training->notRecorded())
        note = tr("The trainee records could not be written (%1); the attempt is kept and will be added the next "
                  "time they can.")
                   .arg(m_training->unwritten());
    else if (m_training->madeDemonstration()) note = tr("This attempt is now the stage's demonstration.");
    m_note->setText(note);
    m_breakdown->setRowCount(int(r.breakdown.size()));
    for (int i = 0; i < int(r.breakdown.size()); ++i) {
        const trainer::ScoreItem& s = r.breakdown[std::size_t(i)];
        QString measured;
        if (s.key == "time") measured = tr("%1 s").arg(num(s.value, 1));
        else if (s.key == "path") measured = tr("%1 %").arg(num(s.value, 0));
        else if (s.key == "smooth") measured = tr("%1 m/s³").arg(num(s.value, 2));
        else if (s.key == "safety") measured = tr("%1 penalty points").arg(num(s.value, 0));
        else measured = num(s.value, 2);
        m_breakdown->setItem(i, 0, new QTableWidgetItem(s.label()));
        m_breakdown->setItem(i, 1, new QTableWidgetItem(measured));
        m_breakdown->setItem(i, 2, new QTableWidgetItem(num(s.points, 1)));
        m_breakdown->setItem(i, 3, new QTableWidgetItem(num(s.max, 0)));
        for (int c = 1; c < 4; ++c) m_breakdown->item(i, c)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    }
    m_improvements->clear();
    const QStringList advice = r.improvements();
    m_improvements->addItems(advice.isEmpty() ? QStringList{tr("Nothing: a clean run.")} : advice);
    const int next = m_training->current() + 1;
    m_training->loadProgress();  // the attempt just recorded may unlock the next stage
    const auto& entries = m_training->entries();
    m_nextButton->setEnabled(next < int(entries.size()) && entries[std::size_t(next)].tutorial &&
                             !m_training->isLocked(next));
    const bool recorded = !m_training->recordedInput().isEmpty();
    m_saveDemoButton->setVisible(recorded && !kiosk);  // for trainers
    m_useDemoButton->setVisible(recorded && !kiosk);
}

}  // namespace studio
