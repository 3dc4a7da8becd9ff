#include "ide/studio/station/mapping_table.h"

#include "ide/studio/station/button_spin.h"
#include "ide/studio/station/channel_bars.h"
#include "ide/studio/station/live_state.h"
#include "trainer/station/control_names.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHash>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace studio {

namespace {

/// The kinds a mapping can name instead of a device id.
const QStringList& kindKeys()
{
    static const QStringList keys{QStringLiteral("gamepad"), QStringLiteral("joystick"), QStringLiteral("serial"),
                                  QStringLiteral("comedi"), QStringLiteral("keyboard")};
    return keys;
}

constexpr int kMaxButton = 127;
constexpr int kGenericAxes = 8;  // axes offered for a device that is not there

QComboBox* editableCombo(QWidget* parent)
{
    auto* c = new QComboBox(parent);
    c->setEditable(true);
    c->setInsertPolicy(QComboBox::NoInsert);
    c->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    c->setMinimumContentsLength(8);
    return c;
}

void setButtonSpinTexts(QSpinBox* s)
{
    s->setSpecialValueText(MappingTable::tr("none"));
    s->setToolTip(MappingTable::tr("The button's number on that device (as the channel lamps show it)"));
}

QSpinBox* buttonSpin(QWidget* parent)
{
    auto* s = new ButtonSpin(parent);
    s->setRange(-1, kMaxButton);
    setButtonSpinTexts(s);
    return s;
}

}  // namespace

MappingTable::MappingTable(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);

    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    QHeaderView* h = m_table->horizontalHeader();
    h->setSectionResizeMode(QHeaderView::Interactive);
    h->setSectionResizeMode(DriveColumn, QHeaderView::Stretch);
    // (narrow enough for the page at 1280×720 with the Live column in view)
    const int widths[] = {95, 105, 90, 75, 55, 150};
    const int columns[] = {BankColumn, DeviceColumn, AxisColumn, GainColumn, SignColumn, LiveColumn};
    int fixed = 0;
    for (int i = 0; i < 6; ++i) {
        m_table->setColumnWidth(columns[i], widths[i]);
        fixed += widths[i];
    }
    // room for a drive's name beside the fixed columns
    m_table->setMinimumWidth(fixed + 100);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->verticalHeader()->defaultSectionSize() + 4);
    layout->addWidget(m_table, 3);

    auto* rowButtons = new QHBoxLayout;
    auto* add = new QPushButton(this);
    m_removeMapping = new QPushButton(this);
    connect(add, &QPushButton::clicked, this, [this] { addMapping(); });
    connect(m_removeMapping, &QPushButton::clicked, this, [this] {
        if (m_table->currentRow() >= 0) removeMapping(m_table->currentRow());
    });
    rowButtons->addWidget(add);
    rowButtons->addWidget(m_removeMapping);
    rowButtons->addStretch(1);
    layout->addLayout(rowButtons);

    auto* banksTitle = new QLabel(this);
    QFont bold = banksTitle->font();
    bold.setBold(true);
    banksTitle->setFont(bold);
    layout->addSpacing(6);
    layout->addWidget(banksTitle);
    auto* banksNote = new QLabel(this);
    banksNote->setWordWrap(true);
    layout->addWidget(banksNote);

    m_banksTable = new QTableWidget(0, BankColumnCount, this);
    m_banksTable->verticalHeader()->hide();
    m_banksTable->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_banksTable->setSelectionMode(QAbstractItemView::SingleSelection);
    m_banksTable->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_banksTable->horizontalHeader()->setSectionResizeMode(BankNameColumn, QHeaderView::Stretch);
    m_banksTable->setColumnWidth(SelectDeviceColumn, 200);
    m_banksTable->setColumnWidth(SelectButtonColumn, 100);
    m_banksTable->verticalHeader()->setDefaultSectionSize(m_banksTable->verticalHeader()->defaultSectionSize() + 4);
    layout->addWidget(m_banksTable, 1);
    connect(m_banksTable, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
        if (m_filling || item->column() != BankNameColumn || item->row() >= m_banks.size()) return;
        // (a renamed bank is shown as typed: the profile's translations are of the old name)
        m_banks[item->row()].name = item->text().trimmed();
        refreshBankCombos();
        changed();
    });

    auto* bankButtons = new QHBoxLayout;
    auto* addBankButton = new QPushButton(this);
    m_renameBank = new QPushButton(this);
    m_removeBank = new QPushButton(this);
    connect(addBankButton, &QPushButton::clicked, this, [this] {
        const int b = addBank();
        m_banksTable->setCurrentCell(b, BankNameColumn);
        m_banksTable->editItem(m_banksTable->item(b, BankNameColumn));
    });
    connect(m_renameBank, &QPushButton::clicked, this, [this] {
        if (QTableWidgetItem* item = m_banksTable->item(m_banksTable->currentRow(), BankNameColumn))
            m_banksTable->editItem(item);
    });
    connect(m_removeBank, &QPushButton::clicked, this, [this] {
        if (m_banksTable->currentRow() >= 0) removeBank(m_banksTable->currentRow());
    });
    bankButtons->addWidget(addBankButton);
    bankButtons->addWidget(m_renameBank);
    bankButtons->addWidget(m_removeBank);
    bankButtons->addStretch(1);
    auto* nextLabel = new QLabel(this);
    bankButtons->addWidget(nextLabel);
    m_nextDevice = editableCombo(this);
    m_nextButton = buttonSpin(this);
    m_texts.add([=, this] {
        m_table->setHorizontalHeaderLabels({tr("Bank"), tr("Device"), tr("Axis"), tr("Drive"), tr("Gain"), tr("Sign"),
                                            tr("Live")});
        m_table->horizontalHeaderItem(DeviceColumn)
            ->setToolTip(tr("A device id, or a kind (gamepad, joystick, serial, comedi, keyboard): the first "
                            "connected device of that kind"));
        m_table->horizontalHeaderItem(GainColumn)->setToolTip(tr("Command = gain × sign × calibrated value (0 … 10)"));
        m_table->horizontalHeaderItem(LiveColumn)
            ->setToolTip(tr("What the mapping gives its drive now; after a profile change, a bank switch or a "
                            "reconnection it waits until the lever is back at the centre"));
        add->setText(tr("Add mapping"));
        add->setToolTip(tr("A new row in the selected row's bank"));
        m_removeMapping->setText(tr("Remove mapping"));
        banksTitle->setText(tr("Banks"));
        banksNote->setText(tr("A device with fewer axes than the machine has drives switches between banks of "
                              "mappings with its buttons; the “Always” mappings act in every bank."));
        m_banksTable->setHorizontalHeaderLabels({tr("Bank"), tr("Selected by device"), tr("Button")});
        addBankButton->setText(tr("Add bank"));
        m_renameBank->setText(tr("Rename bank"));
        m_removeBank->setText(tr("Remove bank"));
        nextLabel->setText(tr("Next bank:"));
        m_nextDevice->setToolTip(tr("The device whose button steps to the next bank"));
        setButtonSpinTexts(m_nextButton);
        m_nextButton->setMinimumWidth(m_nextButton->sizeHint().width());  // "ninguno" whole
    });
    bankButtons->addWidget(m_nextDevice);
    bankButtons->addWidget(m_nextButton);
    layout->addLayout(bankButtons);
    auto nextChanged = [this] {
        if (m_filling) return;
        const trainer::ButtonRef ref{m_nextDevice->currentText().trimmed(), m_nextButton->value()};
        m_nextBank = ref.isSet() ? ref : trainer::ButtonRef{};
        refreshButtonNames();
        changed();
    };
    connect(m_nextDevice, &QComboBox::currentTextChanged, this, nextChanged);
    connect(m_nextButton, &QSpinBox::valueChanged, this, nextChanged);

    auto selection = [this] {
        m_removeMapping->setEnabled(m_table->currentRow() >= 0);
        m_removeBank->setEnabled(m_banksTable->currentRow() >= 0);
        m_renameBank->setEnabled(m_banksTable->currentRow() >= 0);
    };
    connect(m_table, &QTableWidget::currentCellChanged, this, selection);
    connect(m_banksTable, &QTableWidget::currentCellChanged, this, selection);
    selection();
}

MappingTable::~MappingTable() = default;

void MappingTable::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        m_texts.apply();
        // the cells (bank and axis names, "none", tooltips, the issues) made again; the
        // live column at the next showState()
        rebuildBanks();
        rebuildRows();
    }
    QWidget::changeEvent(event);
}

void MappingTable::setDrives(const QList<trainer::DriveInfo>& drives)
{
    m_drives = drives;
    rebuildRows();
}

void MappingTable::setProfile(const trainer::StationProfile& profile)
{
    m_rows.clear();
    for (const trainer::Mapping& m : profile.always) m_rows.append({-1, m});
    m_banks = profile.banks;
    for (int b = 0; b < m_banks.size(); ++b) {
        for (const trainer::Mapping& m : m_banks[b].mappings) m_rows.append({b, m});
        m_banks[b].mappings.clear();
    }
    m_nextBank = profile.nextBank;
    m_labels.translations = profile.translations;
    rebuildBanks();
    rebuildRows();
}

void MappingTable::writeTo(trainer::StationProfile& profile) const
{
    profile.always.clear();
    profile.banks = m_banks;
    for (trainer::Bank& b : profile.banks) b.mappings.clear();
    for (const Row& r : m_rows) {
        if (r.bank < 0) profile.always.append(r.mapping);
        else if (r.bank < profile.banks.size()) profile.banks[r.bank].mappings.append(r.mapping);
    }
    profile.nextBank = m_nextBank;
}

// ---- choices -------------------------------------------------------------------

const MappingTable::DeviceChoice* MappingTable::resolve(const QString& device) const
{
    const DeviceChoice* firstOfKind = nullptr;
    for (const DeviceChoice& d : m_devices) {
        if (d.id == device) return &d;
        if (d.kind == device) {
            if (d.connected) return &d;
            if (!firstOfKind) firstOfKind = &d;
        }
    }
    return firstOfKind;
}

void MappingTable::fillBankCombo(QComboBox* combo, int bank) const
{
    const QSignalBlocker block(combo);
    combo->clear();
    combo->addItem(tr("Always"), -1);
    for (int b = 0; b < m_banks.size(); ++b)
        combo->addItem(m_banks[b].name.isEmpty() ? tr("Bank %1").arg(b + 1) : m_labels.localized(m_banks[b].name), b);
    combo->setCurrentIndex(std::max(0, combo->findData(bank)));
}

void MappingTable::fillDeviceCombo(QComboBox* combo, const QString& device) const
{
    const QSignalBlocker block(combo);
    combo->clear();
    for (const QString& k : kindKeys()) {
        combo->addItem(k);
        combo->setItemData(combo->count() - 1, tr("The first connected device of this kind"), Qt::ToolTipRole);
    }
    for (const DeviceChoice& d : m_devices) {
        if (combo->findText(d.id) >= 0) continue;
        combo->addItem(d.id);
        combo->setItemData(combo->count() - 1, d.name, Qt::ToolTipRole);
    }
    combo->setCurrentText(device);
}

void MappingTable::fillAxisCombo(QComboBox* combo, const QString& device, int axis) const
{
    const QSignalBlocker block(combo);
    combo->clear();
    const DeviceChoice* d = resolve(device);
    if (isGamepad(device)) {
        // SDL's game-controller axes, by name: the index means nothing to a person
        for (int a = 0; !trainer::gamepadAxisName(a).isEmpty() || a <= axis; ++a) {
            const QString name = trainer::gamepadAxisName(a);
            combo->addItem(name.isEmpty() ? tr("Axis %1").arg(a) : name, a);
        }
        combo->setCurrentIndex(std::max(0, combo->findData(axis)));
        return;
    }
    const int count = std::max(d ? int(d->axes.size()) : kGenericAxes, axis + 1);
    for (int a = 0; a < count; ++a) {
        const QString name = d && a < d->axes.size() ? d->axes[a] : QString();
        combo->addItem(name.isEmpty() ? tr("Axis %1").arg(a) : QStringLiteral("%1: %2").arg(a).arg(name), a);
    }
    combo->setCurrentIndex(std::max(0, combo->findData(axis)));
}

bool MappingTable::isGamepad(const QString& device) const
{
    const DeviceChoice* d = resolve(device);
    const QString pad = trainer::kindKey(trainer::DeviceKind::Gamepad);
    return device.trimmed() == pad || (d && d->kind == pad);
}

void MappingTable::refreshButtonNames()
{
    const auto name = [this](QSpinBox* spin, const QComboBox* device) {
        if (auto* s = qobject_cast<ButtonSpin*>(spin); s && device) s->setGamepad(isGamepad(device->currentText()));
    };
    for (int b = 0; b < m_banksTable->rowCount(); ++b) name(selectButtonSpin(b), selectDeviceCombo(b));
    name(m_nextButton, m_nextDevice);
}

void MappingTable::fillDriveCombo(QComboBox* combo, int drive) const
{
    const QSignalBlocker block(combo);
    combo->clear();
    for (const trainer::DriveInfo& d : m_drives) combo->addItem(d.label(), d.jointId);
    if (combo->findData(drive) < 0) {
        combo->addItem(tr("C %1 (not in this model)").arg(drive), drive);
        combo->setItemData(combo->count() - 1, redColor(), Qt::ForegroundRole);
    }
    combo->setCurrentIndex(combo->findData(drive));
}

// ---- rows ----------------------------------------------------------------------

int MappingTable::rowOf(const QWidget* cellWidget, int column) const
{
    for (int r = 0; r < m_table->rowCount(); ++r)
        if (m_table->cellWidget(r, column) == cellWidget) return r;
    return -1;
}

void MappingTable::buildRow(int r)
{
    const Row& row = m_rows[r];
    auto* bank = new QComboBox(m_table);
    fillBankCombo(bank, row.bank);
    auto* device = editableCombo(m_table);
    fillDeviceCombo(device, row.mapping.device);
    auto* axis = new QComboBox(m_table);
    fillAxisCombo(axis, row.mapping.device, row.mapping.axis);
    auto* drive = new QComboBox(m_table);
    fillDriveCombo(drive, row.mapping.drive);
    auto* gain = new QDoubleSpinBox(m_table);
    gain->setRange(0.0, trainer::Mapping::kMaxGain);
    gain->setDecimals(2);
    gain->setSingleStep(0.1);
    gain->setValue(row.mapping.gain);
    auto* sign = new QComboBox(m_table);
    sign->addItem(QStringLiteral("+"), 1);
    sign->addItem(QStringLiteral("−"), -1);
    sign->setCurrentIndex(row.mapping.sign < 0 ? 1 : 0);
    sign->setToolTip(tr("−: the lever drives the valve the other way"));
    for (QWidget* w : std::initializer_list<QWidget*>{bank, device, axis, drive, gain, sign}) guardWheel(w);
    m_table->setCellWidget(r, BankColumn, bank);
    m_table->setCellWidget(r, DeviceColumn, device);
    m_table->setCellWidget(r, AxisColumn, axis);
    m_table->setCellWidget(r, DriveColumn, drive);
    m_table->setCellWidget(r, GainColumn, gain);
    m_table->setCellWidget(r, SignColumn, sign);
    auto* live = new QTableWidgetItem;
    live->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    m_table->setItem(r, LiveColumn, live);
    // the cells' own items (under the widgets) make the row selectable by a click anywhere
    for (int c = 0; c < LiveColumn; ++c) {
        auto* item = new QTableWidgetItem;
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
        m_table->setItem(r, c, item);
    }

    connect(bank, &QComboBox::currentIndexChanged, this, [this, bank] {
        const int r = rowOf(bank, BankColumn);
        if (r < 0) return;
        m_rows[r].bank = bank->currentData().toInt();
        changed();
    });
    connect(device, &QComboBox::currentTextChanged, this, [this, device] {
        const int r = rowOf(device, DeviceColumn);
        if (r < 0) return;
        m_rows[r].mapping.device = device->currentText().trimmed();
        fillAxisCombo(axisCombo(r), m_rows[r].mapping.device, m_rows[r].mapping.axis);
        changed();
    });
    connect(axis, &QComboBox::currentIndexChanged, this, [this, axis] {
        const int r = rowOf(axis, AxisColumn);
        if (r < 0 || axis->currentIndex() < 0) return;
        m_rows[r].mapping.axis = axis->currentData().toInt();
        changed();
    });
    connect(drive, &QComboBox::currentIndexChanged, this, [this, drive] {
        const int r = rowOf(drive, DriveColumn);
        if (r < 0 || drive->currentIndex() < 0) return;
        m_rows[r].mapping.drive = drive->currentData().toInt();
        changed();
    });
    connect(gain, &QDoubleSpinBox::valueChanged, this, [this, gain](double v) {
        const int r = rowOf(gain, GainColumn);
        if (r < 0) return;
        m_rows[r].mapping.gain = v;
        changed();
    });
    connect(sign, &QComboBox::currentIndexChanged, this, [this, sign] {
        const int r = rowOf(sign, SignColumn);
        if (r < 0) return;
        m_rows[r].mapping.sign = sign->currentData().toInt();
        changed();
    });
}

void MappingTable::rebuildRows()
{
    m_filling = true;
    const int current = m_table->currentRow();
    m_table->setRowCount(0);
    m_table->setRowCount(int(m_rows.size()));
    for (int r = 0; r < m_rows.size(); ++r) buildRow(r);
    if (current >= 0 && current < m_rows.size()) m_table->setCurrentCell(current, LiveColumn);
    m_filling = false;
    refreshIssues();
}

void MappingTable::rebuildBanks()
{
    m_filling = true;
    const int current = m_banksTable->currentRow();
    m_banksTable->setRowCount(0);
    m_banksTable->setRowCount(int(m_banks.size()));
    for (int b = 0; b < m_banks.size(); ++b) {
        m_banksTable->setItem(b, BankNameColumn, new QTableWidgetItem(m_labels.localized(m_banks[b].name)));
        auto* device = editableCombo(m_banksTable);
        const trainer::ButtonRef ref = m_banks[b].select.value(0);
        fillDeviceCombo(device, ref.device);
        auto* button = buttonSpin(m_banksTable);
        button->setValue(ref.button);
        if (m_banks[b].select.size() > 1)
            device->setToolTip(tr("%n more button(s) of the profile also select this bank", nullptr,
                                  int(m_banks[b].select.size() - 1)));
        guardWheel(device);
        guardWheel(button);
        m_banksTable->setCellWidget(b, SelectDeviceColumn, device);
        m_banksTable->setCellWidget(b, SelectButtonColumn, button);
        // the column as wide as the spin box asks ("none" may be longer in the language)
        m_banksTable->setColumnWidth(SelectButtonColumn,
                                     std::max(m_banksTable->columnWidth(SelectButtonColumn), button->sizeHint().width()));
        auto selectChanged = [this, device, button] {
            if (m_filling) return;
            int bank = -1;
            for (int i = 0; i < m_banksTable->rowCount(); ++i)
                if (m_banksTable->cellWidget(i, SelectDeviceColumn) == device) bank = i;
            if (bank < 0) return;
            const trainer::ButtonRef ref{device->currentText().trimmed(), button->value()};
            QList<trainer::ButtonRef>& select = m_banks[bank].select;
            if (ref.isSet()) {
                if (select.isEmpty()) select.append(ref);
                else select[0] = ref;
            } else if (!select.isEmpty()) {
                select.removeFirst();
            }
            refreshButtonNames();
            changed();
        };
        connect(device, &QComboBox::currentTextChanged, this, selectChanged);
        connect(button, &QSpinBox::valueChanged, this, selectChanged);
    }
    fillDeviceCombo(m_nextDevice, m_nextBank.device);
    {
        const QSignalBlocker block(m_nextButton);
        m_nextButton->setValue(m_nextBank.isSet() ? m_nextBank.button : -1);
    }
    if (current >= 0 && current < m_banks.size()) m_banksTable->setCurrentCell(current, BankNameColumn);
    refreshButtonNames();
    m_filling = false;
}

void MappingTable::refreshBankCombos()
{
    for (int r = 0; r < m_rows.size(); ++r)
        if (QComboBox* c = bankCombo(r)) fillBankCombo(c, m_rows[r].bank);
}

void MappingTable::refreshIssues()
{
    trainer::StationProfile p;
    writeTo(p);
    // the check's "where" of each row
    QHash<QString, int> rowOfPath;
    QList<int> perBank(m_banks.size(), 0);
    int always = 0;
    for (int r = 0; r < m_rows.size(); ++r) {
        const int b = m_rows[r].bank;
        if (b < 0) rowOfPath.insert(QStringLiteral("always[%1]").arg(always++), r);
        else if (b < m_banks.size()) rowOfPath.insert(QStringLiteral("banks[%1].mappings[%2]").arg(b).arg(perBank[b]++), r);
    }
    m_issues = QStringList(int(m_rows.size()), QString());
    for (const trainer::ProfileIssue& issue : p.check(m_drives)) {
        const int r = rowOfPath.value(issue.where, -1);
        if (r < 0) continue;
        m_issues[r] = m_issues[r].isEmpty() ? issue.message : m_issues[r] + QLatin1Char('\n') + issue.message;
    }
    for (int r = 0; r < m_rows.size(); ++r) {
        QTableWidgetItem* live = m_table->item(r, LiveColumn);
        if (!live) continue;
        if (!m_issues[r].isEmpty()) {
            live->setText(m_issues[r]);
            live->setForeground(redColor());
            live->setToolTip(m_issues[r]);
        }
    }
}

void MappingTable::changed()
{
    if (m_filling) return;
    refreshIssues();
    emit edited();
}

void MappingTable::guardWheel(QWidget* cellWidget)
{
    cellWidget->setFocusPolicy(Qt::StrongFocus);
    cellWidget->installEventFilter(this);
}

bool MappingTable::eventFilter(QObject* watched, QEvent* event)
{
    // scrolling the table must not turn the combo or spin box under the pointer (a gain
    // or a drive changed by accident): the wheel edits only a focused cell
    if (event->type() == QEvent::Wheel) {
        auto* w = qobject_cast<QWidget*>(watched);
        if (w && !w->hasFocus()) {
            if (QWidget* viewport = w->parentWidget()) QCoreApplication::sendEvent(viewport, event);  // scrolls
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

// ---- state ---------------------------------------------------------------------

void MappingTable::showState(const trainer::StationState& state)
{
    // device choices
    QList<DeviceChoice> devices;
    QString key;
    for (const trainer::DeviceState& d : state.devices) {
        if (d.replay) continue;
        DeviceChoice c{d.info.id, trainer::kindKey(d.info.kind), trainer::displayName(d.info), {},
                       d.status == trainer::DeviceStatus::Connected};
        for (const trainer::AxisInfo& a : d.info.axes) c.axes.append(a.name);
        key += c.id + QLatin1Char('|') + c.axes.join(QLatin1Char(',')) + QLatin1Char('|') + QString::number(c.connected) + QLatin1Char(';');
        devices.append(c);
    }
    if (key != m_devicesKey) {
        m_devicesKey = key;
        m_devices = devices;
        m_filling = true;
        for (int r = 0; r < m_rows.size(); ++r) {
            if (QComboBox* c = deviceCombo(r); c && !c->hasFocus()) fillDeviceCombo(c, m_rows[r].mapping.device);
            if (QComboBox* c = axisCombo(r)) fillAxisCombo(c, m_rows[r].mapping.device, m_rows[r].mapping.axis);
        }
        for (int b = 0; b < m_banks.size(); ++b)
            if (QComboBox* c = selectDeviceCombo(b); c && !c->hasFocus()) fillDeviceCombo(c, m_banks[b].select.value(0).device);
        if (!m_nextDevice->hasFocus()) fillDeviceCombo(m_nextDevice, m_nextBank.device);
        refreshButtonNames();
        m_filling = false;
    }

    // the active bank in bold
    for (int b = 0; b < m_banksTable->rowCount(); ++b) {
        if (QTableWidgetItem* item = m_banksTable->item(b, BankNameColumn)) {
            QFont f = item->font();
            if (f.bold() != (b == state.activeBank)) {
                f.setBold(b == state.activeBank);
                const QSignalBlocker block(m_banksTable);
                item->setFont(f);
            }
        }
    }

    // the live column: rows in the engine's order (always, then bank by bank)
    QList<int> order;
    for (int r = 0; r < m_rows.size(); ++r)
        if (m_rows[r].bank < 0) order.append(r);
    for (int b = 0; b < m_banks.size(); ++b)
        for (int r = 0; r < m_rows.size(); ++r)
            if (m_rows[r].bank == b) order.append(r);
    QList<const trainer::MappingState*> stateOf(m_rows.size(), nullptr);
    for (int k = 0; k < order.size() && k < state.mappings.size(); ++k) {
        const trainer::MappingState& ms = state.mappings[k];
        const Row& row = m_rows[order[k]];
        if (ms.mapping == row.mapping && ms.bank == row.bank) stateOf[order[k]] = &ms;
    }
    for (int r = 0; r < m_rows.size(); ++r) {
        QTableWidgetItem* live = m_table->item(r, LiveColumn);
        if (!live || !m_issues.value(r).isEmpty()) continue;
        const trainer::MappingState* ms = stateOf[r];
        QString text, tip;
        QColor color = palette().color(QPalette::Text);
        if (!ms) {
            text = QStringLiteral("…");
        } else if (ms->treeJoint < 0) {
            text = tr("ignored");
            tip = tr("The model has no such drive, or the gain or sign is not valid");
            color = redColor();
        } else if (ms->deviceId.isEmpty()) {
            text = tr("no %1 found").arg(ms->mapping.device);
            color = amberColor();
        } else if (!ms->connected) {
            text = tr("device not connected");
            color = amberColor();
        } else if (ms->bank >= 0 && ms->bank != state.activeBank) {
            text = tr("bank not active");
            color = palette().color(QPalette::PlaceholderText);
        } else if (!ms->armed) {
            text = tr("waiting for centre");
            tip = tr("Bring the lever back to the centre to take over this drive");
            color = amberColor();
        } else {
            text = formatValue(ms->contribution);
            tip = tr("Contribution to the drive's command now (device %1)").arg(ms->deviceId);
        }
        if (live->text() != text) live->setText(text);
        if (live->toolTip() != tip) live->setToolTip(tip);
        if (live->foreground().color() != color) live->setForeground(color);
    }
}

// ---- edits ---------------------------------------------------------------------

int MappingTable::addMapping()
{
    Row row;
    const int current = m_table->currentRow();
    if (current >= 0 && current < m_rows.size()) {
        row.bank = m_rows[current].bank;
        row.mapping.device = m_rows[current].mapping.device;
    } else {
        row.bank = m_banks.isEmpty() ? -1 : 0;
        const auto pad = std::find_if(m_devices.begin(), m_devices.end(), [](const DeviceChoice& d) {
            return d.kind == QLatin1String("gamepad") || d.kind == QLatin1String("joystick");
        });
        row.mapping.device = pad != m_devices.end() ? pad->kind
                             : m_devices.isEmpty()  ? QStringLiteral("gamepad")
                                                    : m_devices.first().id;
    }
    // the first drive not yet mapped in that bank
    row.mapping.drive = m_drives.isEmpty() ? 1 : m_drives.first().jointId;
    for (const trainer::DriveInfo& d : m_drives) {
        const bool used = std::any_of(m_rows.begin(), m_rows.end(), [&](const Row& r) {
            return (r.bank == row.bank || r.bank < 0) && r.mapping.drive == d.jointId;
        });
        if (!used) {
            row.mapping.drive = d.jointId;
            break;
        }
    }
    m_rows.append(row);
    const int r = int(m_rows.size()) - 1;
    m_filling = true;
    m_table->setRowCount(r + 1);
    buildRow(r);
    m_filling = false;
    m_table->setCurrentCell(r, LiveColumn);
    changed();
    return r;
}

void MappingTable::removeMapping(int row)
{
    if (row < 0 || row >= m_rows.size()) return;
    m_rows.removeAt(row);
    m_table->removeRow(row);
    changed();
}

int MappingTable::addBank(const QString& name)
{
    trainer::Bank b;
    b.name = name.isEmpty() ? tr("Bank %1").arg(m_banks.size() + 1) : name;
    m_banks.append(b);
    rebuildBanks();
    refreshBankCombos();
    changed();
    return int(m_banks.size()) - 1;
}

void MappingTable::renameBank(int bank, const QString& name)
{
    if (bank < 0 || bank >= m_banks.size()) return;
    // through the item: its change updates the bank and the combos
    if (QTableWidgetItem* item = m_banksTable->item(bank, BankNameColumn)) item->setText(name);
}

bool MappingTable::removeBank(int bank)
{
    if (bank < 0 || bank >= m_banks.size()) return false;
    const int count = int(std::count_if(m_rows.begin(), m_rows.end(), [&](const Row& r) { return r.bank == bank; }));
    if (count > 0 && m_confirm &&
        !m_confirm(tr("Remove the bank “%1” and its %n mapping(s)?", nullptr, count).arg(m_labels.localized(m_banks[bank].name))))
        return false;
    m_rows.erase(std::remove_if(m_rows.begin(), m_rows.end(), [&](const Row& r) { return r.bank == bank; }),
                 m_rows.end());
    for (Row& r : m_rows)
        if (r.bank > bank) --r.bank;
    m_banks.removeAt(bank);
    rebuildBanks();
    rebuildRows();
    changed();
    return true;
}

// ---- access --------------------------------------------------------------------

QString MappingTable::liveText(int row) const
{
    const QTableWidgetItem* item = m_table->item(row, LiveColumn);
    return item ? item->text() : QString();
}

QString MappingTable::issueText(int row) const
{
    return m_issues.value(row);
}

QComboBox* MappingTable::bankCombo(int row) const
{
    return qobject_cast<QComboBox*>(m_table->cellWidget(row, BankColumn));
}

QComboBox* MappingTable::deviceCombo(int row) const
{
    return qobject_cast<QComboBox*>(m_table->cellWidget(row, DeviceColumn));
}

QComboBox* MappingTable::axisCombo(int row) const
{
    return qobject_cast<QComboBox*>(m_table->cellWidget(row, AxisColumn));
}

QComboBox* MappingTable::driveCombo(int row) const
{
    return qobject_cast<QComboBox*>(m_table->cellWidget(row, DriveColumn));
}

QDoubleSpinBox* MappingTable::gainSpin(int row) const
{
    return qobject_cast<QDoubleSpinBox*>(m_table->cellWidget(row, GainColumn));
}

QComboBox* MappingTable::signCombo(int row) const
{
    return qobject_cast<QComboBox*>(m_table->cellWidget(row, SignColumn));
}

QComboBox* MappingTable::selectDeviceCombo(int bank) const
{
    return qobject_cast<QComboBox*>(m_banksTable->cellWidget(bank, SelectDeviceColumn));
}

QSpinBox* MappingTable::selectButtonSpin(int bank) const
{
    return qobject_cast<QSpinBox*>(m_banksTable->cellWidget(bank, SelectButtonColumn));
}

}  // namespace studio
