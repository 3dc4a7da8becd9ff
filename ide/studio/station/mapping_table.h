#pragma once
// MappingTable: the valve mapping of a station profile, edited in place.
//  - Mappings, one row each: Bank (Always, or a bank), Device (an id, or a kind that
//    matches the first connected device of that kind), Axis, Drive (the model's drives
//    by label), Gain, Sign, and a live column: the mapping's contribution to its
//    drive's command now, "waiting for centre" while not armed, or why it does nothing.
//    A mapping the profile's check flags (a drive the model lacks…) shows the issue.
//  - Banks: name, the button that selects it (device + button number), and the
//    next-bank button.
// Every edit changes the table's copy and emits edited(); the owner takes the result
// with writeTo() (the Station page re-installs the profile so the edit acts at once).
// showState() fills the live column and the device choices from the station's state.

#include "trainer/station/station_engine.h"
#include "ide/i18n/texts.h"

#include <QList>
#include <QStringList>
#include <QWidget>

#include <functional>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace studio {

class MappingTable : public QWidget {
    Q_OBJECT
public:
    enum Column { BankColumn, DeviceColumn, AxisColumn, DriveColumn, GainColumn, SignColumn, LiveColumn, ColumnCount };
    enum BankColumnIndex { BankNameColumn, SelectDeviceColumn, SelectButtonColumn, BankColumnCount };

    explicit MappingTable(QWidget* parent = nullptr);
    ~MappingTable() override;

    /// The model's drives (the Drive column's choices).
    void setDrives(const QList<trainer::DriveInfo>& drives);
    /// Shows the mappings, banks and next-bank button of `profile` (rows rebuilt).
    void setProfile(const trainer::StationProfile& profile);
    /// Writes the mappings (always and per bank), the banks and the next-bank button
    /// into `profile`; the rest of it is left alone.
    void writeTo(trainer::StationProfile& profile) const;
    /// The live column and the device choices, from the station's newest state.
    void showState(const trainer::StationState& state);

    /// Asked before something with contents is removed (a bank with mappings); true:
    /// go on. Unset: always go on.
    void setConfirm(std::function<bool(const QString& question)> confirm) { m_confirm = std::move(confirm); }

    // edits (the buttons call these)
    /// Adds a mapping (in the selected row's bank, else the first bank) and returns its row.
    int addMapping();
    void removeMapping(int row);
    /// Adds a bank ("Bank n" when `name` is empty) and returns its index.
    int addBank(const QString& name = {});
    void renameBank(int bank, const QString& name);
    /// Removes a bank and its mappings (asks first when it has any). False: kept.
    bool removeBank(int bank);

    int rowCount() const { return int(m_rows.size()); }
    int bankCount() const { return int(m_banks.size()); }
    /// The mapping of `row` and its bank (−1: always).
    trainer::Mapping mapping(int row) const { return m_rows.value(row).mapping; }
    int bankOf(int row) const { return m_rows.value(row).bank; }
    /// The live column's text and the row's issue ("" none).
    QString liveText(int row) const;
    QString issueText(int row) const;

    QTableWidget* table() const { return m_table; }
    QTableWidget* banksTable() const { return m_banksTable; }
    QComboBox* bankCombo(int row) const;
    QComboBox* deviceCombo(int row) const;
    QComboBox* axisCombo(int row) const;
    QComboBox* driveCombo(int row) const;
    QDoubleSpinBox* gainSpin(int row) const;
    QComboBox* signCombo(int row) const;
    QComboBox* selectDeviceCombo(int bank) const;
    QSpinBox* selectButtonSpin(int bank) const;
    QComboBox* nextBankDeviceCombo() const { return m_nextDevice; }
    QSpinBox* nextBankButtonSpin() const { return m_nextButton; }

    bool eventFilter(QObject* watched, QEvent* event) override;

signals:
    void edited();

protected:
    /// QEvent::LanguageChange: headers, buttons and cells again.
    void changeEvent(QEvent* event) override;

private:
    struct Row {
        int bank = -1;
        trainer::Mapping mapping;
    };
    struct DeviceChoice {
        QString id;
        QString kind;
        QString name;
        QStringList axes;
        bool connected = false;
    };

    void rebuildRows();
    void rebuildBanks();
    void buildRow(int row);
    void fillBankCombo(QComboBox* combo, int bank) const;
    void fillDeviceCombo(QComboBox* combo, const QString& device) const;
    void fillAxisCombo(QComboBox* combo, const QString& device, int axis) const;
    void fillDriveCombo(QComboBox* combo, int drive) const;
    const DeviceChoice* resolve(const QString& device) const;
    /// `device` (a kind or an id) is a gamepad: its controls are shown by name.
    bool isGamepad(const QString& device) const;
    /// The bank buttons' spin boxes name a gamepad's buttons ("Left shoulder").
    void refreshButtonNames();
    int rowOf(const QWidget* cellWidget, int column) const;
    void refreshIssues();
    void refreshBankCombos();
    void changed();
    void guardWheel(QWidget* cellWidget);

    QList<trainer::DriveInfo> m_drives;
    QList<Row> m_rows;
    QList<trainer::Bank> m_banks;  ///< names and select buttons (their mappings are in m_rows)
    trainer::StationProfile m_labels;  ///< only the profile's translations: bank names as a person reads them
    trainer::ButtonRef m_nextBank;
    QStringList m_issues;          ///< per row
    QList<DeviceChoice> m_devices;
    QString m_devicesKey;
    std::function<bool(const QString&)> m_confirm;
    i18n::Texts m_texts;  ///< the texts that follow the language
    bool m_filling = false;

    QTableWidget* m_table = nullptr;
    QTableWidget* m_banksTable = nullptr;
    QComboBox* m_nextDevice = nullptr;
    QSpinBox* m_nextButton = nullptr;
    QPushButton* m_removeMapping = nullptr;
    QPushButton* m_removeBank = nullptr;
    QPushButton* m_renameBank = nullptr;
};

}  // namespace studio
