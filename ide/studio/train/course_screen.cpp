#include "ide/studio/train/course_screen.h"

#include "ide/i18n/language.h"
#include "ide/studio/train/train_ui.h"
#include "ide/studio/train/training_controller.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace studio {

CourseScreen::CourseScreen(TrainingController* training, QWidget* parent) : QWidget(parent), m_training(training)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(24, 24, 24, 24);
    auto* top = new QHBoxLayout;
    m_title = new QLabel;
    m_title->setObjectName("TrainTitle");
    m_texts.add([this] { m_title->setText(tr("Training course")); });
    top->addWidget(m_title, 1);
    // the languages, each in its own name, big enough for a finger on the kiosk's screen
    auto* languages = new QButtonGroup(this);
    languages->setExclusive(true);
    for (const QString& code : i18n::languages()) {
        auto* b = new QPushButton(i18n::nativeName(code));
        b->setObjectName("LanguageButton_" + code);
        b->setCheckable(true);
        b->setChecked(code == TrainingController::language());
        b->setMinimumSize(190, 64);
        b->setFocusPolicy(Qt::NoFocus);
        b->setStyleSheet("QPushButton { font-size: 18pt; padding: 10px 26px; border: 2px solid #8a949e; "
                         "border-radius: 8px; background: #f4f6f8; color: #1d2329; }"
                         "QPushButton:checked { background: #1f6fc5; border-color: #1f6fc5; color: white; "
                         "font-weight: bold; }");
        languages->addButton(b);
        connect(b, &QPushButton::clicked, this, [code] { i18n::switchTo(code); });
        top->addWidget(b, 0, Qt::AlignVCenter);
        m_languageButtons << b;
    }
    layout->addLayout(top);
    auto* opRow = new QHBoxLayout;
    auto* opLabel = new QLabel;
    m_texts.add([opLabel] { opLabel->setText(tr("Operator:")); });
    opRow->addWidget(opLabel);
    m_operatorBox = new QComboBox;
    m_operatorBox->setObjectName("OperatorBox");
    m_operatorBox->setEditable(true);
    m_operatorBox->setMinimumWidth(240);
    m_operatorBox->addItems(m_training->knownOperators());
    m_operatorBox->setCurrentText(m_training->operatorId());
    m_texts.add([this] { m_operatorBox->lineEdit()->setPlaceholderText(tr("name or number")); });
    connect(m_operatorBox->lineEdit(), &QLineEdit::editingFinished, this,
            [this] { emit operatorChosen(m_operatorBox->currentText()); });
    connect(m_operatorBox, &QComboBox::textActivated, this, &CourseScreen::operatorChosen);
    opRow->addWidget(m_operatorBox);
    opRow->addStretch();
    layout->addLayout(opRow);
    m_courseList = new QListWidget;
    m_courseList->setObjectName("CourseList");
    m_courseList->setStyleSheet("QListWidget { font-size: 16pt; } QListWidget::item { padding: 10px; }");
    layout->addWidget(m_courseList, 1);
    auto* buttons = new QHBoxLayout;
    m_recordsButton = new QPushButton;
    m_recordsButton->setObjectName("RecordsButton");
    m_texts.add([this] {
        m_recordsButton->setText(tr("Records"));
        m_recordsButton->setToolTip(tr("The trainee records: operators, attempts, progress (for the trainer)."));
    });
    connect(m_recordsButton, &QPushButton::clicked, this, &CourseScreen::recordsRequested);
    buttons->addWidget(m_recordsButton);
    buttons->addSpacing(12);
    m_centre = new QLabel;
    m_centre->setObjectName("CentreLinkCourse");
    m_centre->hide();
    buttons->addWidget(m_centre);
    buttons->addStretch();
    m_openButton = new QPushButton;
    m_texts.add([this] { m_openButton->setText(tr("Open")); });
    m_openButton->setEnabled(false);
    buttons->addWidget(m_openButton);
    layout->addLayout(buttons);
    const auto open = [this] {
        QListWidgetItem* it = m_courseList->currentItem();
        if (it && (it->flags() & Qt::ItemIsEnabled)) emit openRequested(it->data(Qt::UserRole).toString());
    };
    connect(m_openButton, &QPushButton::clicked, this, open);
    connect(m_courseList, &QListWidget::itemActivated, this, open);
    connect(m_courseList, &QListWidget::currentItemChanged, this,
            [this](QListWidgetItem* it) { m_openButton->setEnabled(it && (it->flags() & Qt::ItemIsEnabled)); });
}

QPushButton* CourseScreen::languageButton(const QString& code) const
{
    for (QPushButton* b : m_languageButtons)
        if (b->objectName() == "LanguageButton_" + code) return b;
    return nullptr;
}

void CourseScreen::retranslate()
{
    m_texts.apply();
    for (QPushButton* b : m_languageButtons)
        b->setChecked(b->objectName() == "LanguageButton_" + TrainingController::language());
    refresh();
}

void CourseScreen::showOperators()
{
    const QSignalBlocker block(m_operatorBox);
    m_operatorBox->clear();
    m_operatorBox->addItems(m_training->knownOperators());
    m_operatorBox->setCurrentText(m_training->operatorId());
}

void CourseScreen::refresh()
{
    m_training->loadProgress();
    const QString selected = m_courseList->currentItem() ? m_courseList->currentItem()->data(Qt::UserRole).toString()
                                                         : QString();
    m_courseList->clear();
    const auto& entries = m_training->entries();
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const TrainingController::Entry& e = entries[i];
        const CourseProgress p = m_training->progressOf(e.id);
        QString text = tr("Level %1 — %2").arg(e.level).arg(e.title);
        auto* it = new QListWidgetItem;
        it->setData(Qt::UserRole, e.id);
        if (!e.tutorial || !e.problem.isEmpty()) {
            text += "   " + tr("(cannot be used)");
            it->setFlags(it->flags() & ~Qt::ItemIsEnabled);
            it->setToolTip(e.problem.isEmpty() ? tr("This tutorial cannot be loaded.") : e.problem);
        } else if (m_training->isLocked(int(i))) {
            text += "   " + tr("(locked: pass the level before)");
            it->setFlags(it->flags() & ~Qt::ItemIsEnabled);
            it->setToolTip(tr("Pass every stage of the level before to unlock this one."));
        } else {
            text += "   " + trainui::stars(p.stars);
            if (p.attempts > 0) text += "   " + tr("best %1 of 100").arg(trainui::num(p.score, 0));
        }
        it->setText(text);
        m_courseList->addItem(it);
        if (!selected.isEmpty() && e.id == selected) m_courseList->setCurrentItem(it);
    }
}

}  // namespace studio
