#pragma once
// padrob-studio --instructor: the instructor's station of the training centre (docs/
// studio.md "Training centre"). A table of the stations on the network, updated live
// (presence, status, tutorial, operator, attempt time, score, goals, warnings and faults,
// latency); the selected station's machine (a DisplayView, centre screen, driven by the
// same DisplayFeed as a display node) and its event log; and the commands — start a
// tutorial for an operator, pause, resume, reset, stop, inject and clear faults — signed
// with the centre's key, each with the station's reply. Without a key it only watches.
// The bus is polled from a timer in the GUI thread (InstructorNode::poll never blocks).

#include "ide/studio/centre/display_feed.h"
#include "ide/studio/centre/display_view.h"
#include "trainer/centre/bus.h"
#include "trainer/centre/instructor_node.h"
#include "trainer/centre/station_protocol.h"

#include <QMainWindow>

#include <map>
#include <memory>
#include <string>
#include <vector>

class QLabel;
class QMenu;
class QPlainTextEdit;
class QPushButton;
class QTableWidget;
class QTimer;

namespace studio {

class InstructorWindow : public QMainWindow {
    Q_OBJECT
public:
    /// Joins the centre on `bus` (its `reads` are set here) with the key in `keyFile`
    /// ("" none: watching only). Its name is bus.node, by default instructor@HOST:PID, or
    /// instructor@HOST with DDS Security (bus.securityDir: its identity in the PKI).
    InstructorWindow(const trainer::centre::BusOptions& bus, const QString& keyFile, QWidget* parent = nullptr);
    ~InstructorWindow() override;

    enum Column { ColStation, ColPresence, ColStatus, ColTutorial, ColOperator, ColTime, ColScore, ColGoal,
                  ColWarnings, ColLatency, ColumnCount };

    QTableWidget* table() const { return m_table; }
    DisplayView* view() const { return m_view; }
    QPlainTextEdit* eventLog() const { return m_log; }
    /// The latest command's outcome as shown ("" none yet).
    QString replyText() const;
    /// Commands can be sent (a key, and the network).
    bool canCommand() const { return m_node && m_key.isSet(); }
    QString selectedStation() const { return QString::fromStdString(m_selected); }
    /// Selects the row of `station` (false when it is not in the table).
    bool selectStation(const QString& station);
    QPushButton* button(const QString& objectName) const;

    /// A station's refusal code ("bad-signature", "not-running"…) as a sentence.
    static QString refusalText(const std::string& code);

    /// Takes what arrived (the timer calls it every few milliseconds).
    void poll();

public slots:
    void startDialog();
    void faultDialog();
    void sendCommand(const QString& kind, const QString& arg = {}, const QString& arg2 = {},
                     double value = std::numeric_limits<double>::quiet_NaN());

protected:
    void changeEvent(QEvent* event) override;

private:
    struct Pending {
        std::uint64_t nonce = 0;
        std::string station, kind;
        double sentS = 0;
    };
    /// The latest command and what became of it, shown in the language of the moment.
    struct Outcome {
        enum class What { None, Sent, Unsent, Done, Refused, NoReply } what = What::None;
        std::string station, kind, code;
    };
    void showOutcome(Outcome outcome);
    void retranslate();
    void refreshTable();
    void refreshLog();
    void refreshButtons();
    void fillClearMenu();
    void onSelection();
    QString kindLabel(const std::string& kind) const;
    const trainer::centre::StationView* selectedView() const;
    /// "up", "silent" or "left" (InstructorNode's, but a station that withdrew stays left).
    std::string presenceOf(const std::string& name, const trainer::centre::StationView& v) const;

    std::unique_ptr<trainer::centre::Bus> m_bus;
    std::unique_ptr<trainer::centre::InstructorNode> m_node;
    std::string m_nodeName;
    trainer::centre::CentreKey m_key;
    QString m_keyProblem, m_busError;
    DisplayFeed m_feed;
    std::string m_selected;
    std::uint64_t m_fedSeq = ~0ull;
    double m_fedSim = -1;
    std::uint64_t m_fedStarted = 0;
    std::size_t m_logCount = 0;
    std::uint64_t m_logLastSeq = 0;
    std::vector<Pending> m_pending;
    /// Stations that withdrew, by name: the startedMs of the announcement withdrawn. A
    /// late state does not bring them back (InstructorNode would call them "up", then
    /// "silent"); a new announcement does.
    std::map<std::string, std::uint64_t> m_left;
    Outcome m_outcome;
    double m_lastTable = -1;

    QLabel* m_keyLabel;
    QTableWidget* m_table;
    DisplayView* m_view;
    QLabel* m_logTitle;
    QPlainTextEdit* m_log;
    QLabel* m_reply;
    QPushButton *m_start, *m_pause, *m_resume, *m_reset, *m_stop, *m_inject, *m_clear;
    QMenu* m_clearMenu;
    QTimer* m_poll;
};

}  // namespace studio
