#pragma once
// RecordsView: the trainer's view of the trainee records, a screen of
// the Train workspace reached from the course ("Records"):
//  - the operators with their progress (RecordsDb::progress: attempts, tutorials
//    passed, last attempt), and adding one (code and name);
//  - the selected operator's attempts, newest first, and the breakdown and events of
//    the selected attempt;
//  - a chart of the operator's scores (QtCharts): one series per tutorial, the score
//    of each finished or stopped attempt against its number (the operator's attempts
//    in order, 1 = the first), and each tutorial's pass mark as a dashed green line
//    (no attempt series is green: the legend tells the pass marks from the attempts);
//  - Export CSV… (RecordsDb::exportCsv).
// Without records (they could not be opened: locked, read-only, from a newer Padrob…)
// it shows why; training goes on without them (attempts go to pending files).
//
// Language: on QEvent::LanguageChange every text is set again and the records are
// shown anew; an attempt made in another language has its score items and events
// worded again in the current one (from their keys; the tutorial's names when the
// view has the tutorial). Numbers and dates follow the locale; the CSV keeps '.'.

#include "trainer/records/records_db.h"
#include "ide/i18n/texts.h"

#include <QHash>
#include <QWidget>

#include <functional>
#include <memory>
#include <vector>

class QChartView;
class QCheckBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QTableWidget;

namespace trainer {
struct Tutorial;
}

namespace studio {

class RecordsView : public QWidget {
    Q_OBJECT
public:
    explicit RecordsView(QWidget* parent = nullptr);

    /// The records to show (nullptr: none, `problem` says why).
    void setRecords(trainer::records::RecordsDb* db, const QString& problem);
    /// Tutorial titles (in the UI's language) and pass marks (by tutorial id), for the
    /// lists and the chart; the tutorials themselves name parts and people in events.
    void setTutorials(const QHash<QString, QString>& titles, const QHash<QString, double>& passMarks,
                      const QHash<QString, std::shared_ptr<const trainer::Tutorial>>& tutorials = {});
    /// Reads the records again, keeping the selected operator.
    void refresh();
    /// Selects an operator by code (its attempts and chart are shown); false when unknown.
    bool selectOperator(const QString& code);

    /// Adds an operator (as the Add button does). False with `error`.
    bool addOperator(const QString& code, const QString& name, QString* error = nullptr);
    /// Writes every attempt to `path` (as Export CSV… does). False with `error`.
    bool exportCsv(const QString& path, QString* error = nullptr);

    // parts, for tests
    QLabel* message() const { return m_message; }
    /// What the last export wrote, and where (hidden before one).
    QLabel* exportStatus() const { return m_exported; }
    QTableWidget* operatorsTable() const { return m_operators; }
    QTableWidget* attemptsTable() const { return m_attempts; }
    QTableWidget* breakdownTable() const { return m_breakdown; }
    QListWidget* eventsList() const { return m_events; }
    QChartView* chartView() const { return m_chart; }

signals:
    void backRequested();
    /// An operator was added (the course's operator list changes).
    void operatorsChanged();

protected:
    /// QEvent::LanguageChange: every text again, and the records shown anew.
    void changeEvent(QEvent* event) override;

private:
    QString titleOf(const trainer::records::Attempt& a) const;
    QString eventText(const trainer::records::Attempt& a, const trainer::records::AttemptEvent& e) const;
    void showOperator(int row);
    void showAttempt(int row);
    void fillChart(const QList<trainer::records::Attempt>& attempts);

    trainer::records::RecordsDb* m_db = nullptr;
    QString m_problem;
    QHash<QString, QString> m_titles;
    QHash<QString, double> m_passMarks;
    QHash<QString, std::shared_ptr<const trainer::Tutorial>> m_tutorials;
    i18n::Texts m_texts;  ///< the texts that follow the language
    QList<trainer::records::OperatorProgress> m_progress;
    QList<trainer::records::Attempt> m_list;  ///< of the selected operator, newest first

    QLabel* m_message = nullptr;
    QTableWidget* m_operators = nullptr;
    QLineEdit* m_newCode = nullptr;
    QLineEdit* m_newName = nullptr;
    QPushButton* m_add = nullptr;
    QPushButton* m_export = nullptr;
    QLabel* m_exported = nullptr;
    QCheckBox* m_kioskExpert = nullptr;
    QTableWidget* m_attempts = nullptr;
    QTableWidget* m_breakdown = nullptr;
    QListWidget* m_events = nullptr;
    QChartView* m_chart = nullptr;
};

}  // namespace studio
