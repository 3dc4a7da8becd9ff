#include "ide/studio/station/channel_bars.h"

#include "ide/studio/station/live_state.h"
#include "trainer/station/control_names.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QFontDatabase>
#include <QGridLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace studio {

namespace {

/// The locale's numbers without group separators (a raw reading of 32767 is not "32.767").
QLocale numbers()
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale;
}

}  // namespace

QString formatRaw(double raw)
{
    if (!std::isfinite(raw)) return QStringLiteral("—");
    if (raw == std::round(raw) && std::abs(raw) < 1e7) return numbers().toString(qint64(raw));
    return numbers().toString(raw, 'g', 4);
}

QString formatValue(double value)
{
    if (!std::isfinite(value)) return QStringLiteral("—");
    const QLocale locale = numbers();
    const QString s = locale.toString(std::abs(value), 'f', 2);
    if (s == locale.toString(0.0, 'f', 2)) return s;
    return (value < 0 ? QStringLiteral("−") : QStringLiteral("+")) + s;
}

QString formatNumber(double value, int significant)
{
    if (!std::isfinite(value)) return QStringLiteral("—");
    return numbers().toString(value, 'g', significant);
}

// ---- LevelBar ------------------------------------------------------------------

LevelBar::LevelBar(QWidget* parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void LevelBar::setScale(double min, double origin, double max)
{
    if (!(max > min)) max = min + 1.0;
    if (min == m_min && origin == m_origin && max == m_max) return;
    m_min = min;
    m_origin = std::clamp(origin, min, max);
    m_max = max;
    update();
}

void LevelBar::setValue(double value)
{
    if (value == m_value) return;
    m_value = value;
    update();
}

void LevelBar::setMarks(double low, double high)
{
    m_markLow = low;
    m_markHigh = high;
    update();
}

void LevelBar::setBand(double from, double to)
{
    m_bandFrom = from;
    m_bandTo = to;
    update();
}

void LevelBar::setFillColor(const QColor& color)
{
    if (color == m_fill) return;
    m_fill = color;
    update();
}

double LevelBar::fractionOf(double v) const
{
    if (!std::isfinite(v)) return 0.0;
    return std::clamp((v - m_min) / (m_max - m_min), 0.0, 1.0);
}

QSize LevelBar::sizeHint() const
{
    return {160, 16};
}

QSize LevelBar::minimumSizeHint() const
{
    return {60, 12};
}

void LevelBar::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing, false);
    const QRectF r = QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5);
    const double w = r.width();
    auto xOf = [&](double v) { return r.left() + fractionOf(v) * w; };

    p.setPen(palette().color(QPalette::Mid));
    p.setBrush(palette().color(QPalette::Base));
    p.drawRect(r);

    // dead band (or any band), shaded
    if (std::isfinite(m_bandFrom) && std::isfinite(m_bandTo) && m_bandTo > m_bandFrom) {
        QColor shade = palette().color(QPalette::Mid);
        shade.setAlpha(70);
        p.fillRect(QRectF(QPointF(xOf(m_bandFrom), r.top() + 1), QPointF(xOf(m_bandTo), r.bottom())), shade);
    }

    // fill from the origin to the value
    const double x0 = xOf(m_origin), x1 = xOf(m_value);
    const QRectF fill(QPointF(std::min(x0, x1), r.top() + 2), QPointF(std::max(x0, x1), r.bottom() - 1.5));
    if (fill.width() > 0.0) p.fillRect(fill, m_fill);

    // the origin (centre, rest) as a tick
    if (m_origin > m_min && m_origin < m_max) {
        p.setPen(QPen(palette().color(QPalette::WindowText), 1));
        p.drawLine(QPointF(x0, r.top()), QPointF(x0, r.bottom()));
    }

    // marks: the extremes seen
    p.setPen(QPen(QColor(0xd8, 0x1b, 0x60), 2));
    for (double m : {m_markLow, m_markHigh})
        if (std::isfinite(m)) p.drawLine(QPointF(xOf(m), r.top()), QPointF(xOf(m), r.bottom()));
}

// ---- ButtonLamp ----------------------------------------------------------------

ButtonLamp::ButtonLamp(const QString& label, QWidget* parent) : QWidget(parent), m_label(label)
{
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
}

void ButtonLamp::setOn(bool on)
{
    if (on == m_on) return;
    m_on = on;
    update();
}

QSize ButtonLamp::sizeHint() const
{
    const int d = std::max(22, fontMetrics().horizontalAdvance(m_label) + 8);
    return {d, 22};
}

void ButtonLamp::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF r = QRectF(rect()).adjusted(1.5, 1.5, -1.5, -1.5);
    const QColor on(0xff, 0xb3, 0x00), off = palette().color(QPalette::Button);
    p.setPen(QPen(m_on ? on.darker(140) : palette().color(QPalette::Mid), 1));
    p.setBrush(m_on ? on : off);
    p.drawRoundedRect(r, r.height() / 2, r.height() / 2);
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() * 0.8);
    p.setFont(f);
    p.setPen(m_on ? QColor(Qt::black) : palette().color(QPalette::ButtonText));
    p.drawText(r, Qt::AlignCenter, m_label);
}

// ---- ChannelPanel --------------------------------------------------------------

ChannelPanel::ChannelPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_title = new QLabel(this);
    m_title->setWordWrap(true);
    layout->addWidget(m_title);
    m_keyboardNote = new QLabel(this);
    m_keyboardNote->setObjectName(QStringLiteral("keyboardNote"));
    m_keyboardNote->setWordWrap(true);
    m_keyboardNote->hide();
    layout->addWidget(m_keyboardNote);

    m_body = new QWidget(this);
    m_grid = new QGridLayout(m_body);
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_grid->setHorizontalSpacing(8);
    m_grid->setColumnStretch(1, 1);
    m_grid->setColumnStretch(3, 1);
    layout->addWidget(m_body);

    m_buttonsTitle = new QLabel(this);
    layout->addWidget(m_buttonsTitle);
    auto* lamps = new QWidget(this);
    m_lampGrid = new QGridLayout(lamps);
    m_lampGrid->setContentsMargins(0, 0, 0, 0);
    m_lampGrid->setSpacing(4);
    layout->addWidget(lamps);
    layout->addStretch(1);
    m_buttonsTitle->hide();
    retranslate();
}

void ChannelPanel::retranslate()
{
    m_keyboardNote->setText(tr("Keys are digital: a key gives its drive the full command (−1, 0 or +1) at once, so "
                               "there is nothing to calibrate. A ramp eases each key's command in and out instead."));
    m_buttonsTitle->setText(tr("Buttons"));
    if (m_key.isEmpty()) m_title->setText(tr("No device selected"));
}

void ChannelPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        // the rows (headers, flags, buttons' tooltips) are made again at the next setDevice()
        if (!m_key.isEmpty()) m_key = QStringLiteral("?");
    }
    QWidget::changeEvent(event);
}

void ChannelPanel::rebuild(const trainer::DeviceState* device)
{
    m_rows.clear();
    qDeleteAll(m_lamps);
    m_lamps.clear();
    while (QLayoutItem* item = m_grid->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    if (!device) {
        m_title->setText(tr("No device selected"));
        m_buttonsTitle->hide();
        m_keyboardNote->hide();
        return;
    }

    // keys are digital: nothing to calibrate, a ramp instead
    const bool keys = device->info.kind == trainer::DeviceKind::Keyboard;
    m_keyboardNote->setVisible(keys);
    if (device->info.axes.isEmpty()) {
        m_title->setText(tr("%1: no channels (yet)").arg(trainer::displayName(device->info)));
    } else {
        m_title->setText(tr("%1: %n channel(s)", nullptr, int(device->info.axes.size())).arg(trainer::displayName(device->info)));
        const QStringList headers{tr("Channel"), tr("Raw reading"), QString(), tr("Calibrated"), QString(), QString(),
                                  keys ? tr("Ramp") : QString()};
        for (int c = 0; c < headers.size(); ++c) {
            if (headers[c].isEmpty()) continue;
            auto* h = new QLabel(headers[c], m_body);
            QFont f = h->font();
            f.setBold(true);
            h->setFont(f);
            m_grid->addWidget(h, 0, c);
        }
    }
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    const int numberWidth = QFontMetrics(mono).horizontalAdvance(QStringLiteral("−00000")) + 4;
    for (int a = 0; a < device->info.axes.size(); ++a) {
        Row row;
        row.name = new QLabel(trainer::axisName(device->info, a), m_body);
        row.raw = new LevelBar(m_body);
        row.raw->setFillColor(QColor(0x78, 0x90, 0x9c));
        row.rawText = new QLabel(m_body);
        row.rawText->setFont(mono);
        row.rawText->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        row.rawText->setMinimumWidth(numberWidth);
        row.value = new LevelBar(m_body);
        row.value->setScale(-1.0, 0.0, 1.0);
        row.valueText = new QLabel(m_body);
        row.valueText->setFont(mono);
        row.valueText->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        row.valueText->setMinimumWidth(QFontMetrics(mono).horizontalAdvance(QStringLiteral("−0.00")) + 4);
        row.flag = new QLabel(m_body);
        row.flag->setAlignment(Qt::AlignCenter);
        row.flag->setMinimumWidth(fontMetrics().horizontalAdvance(tr("not calibrated")) + 14);
        const int r = a + 1;
        if (keys) {
            row.ramp = new QDoubleSpinBox(m_body);
            row.ramp->setRange(0.0, kMaxRamp);
            row.ramp->setSingleStep(0.05);
            row.ramp->setDecimals(2);
            row.ramp->setSuffix(tr(" s"));
            row.ramp->setSpecialValueText(tr("at once"));
            row.ramp->setToolTip(tr("How long a key takes to open its valve fully (and to close it again): "
                                    "0 gives the full command at once"));
            connect(row.ramp, &QDoubleSpinBox::valueChanged, this, [this, a](double seconds) {
                if (!m_filling) emit rampChanged(a, seconds);
            });
            m_grid->addWidget(row.ramp, r, 6);
        } else {
            row.calibrate = new QPushButton(tr("Calibrate…"), m_body);
            row.calibrate->setToolTip(tr("Capture this channel's centre and travel, and set its dead band and curve"));
            connect(row.calibrate, &QPushButton::clicked, this, [this, a] { emit calibrateRequested(a); });
            m_grid->addWidget(row.calibrate, r, 6);
        }
        m_grid->addWidget(row.name, r, 0);
        m_grid->addWidget(row.raw, r, 1);
        m_grid->addWidget(row.rawText, r, 2);
        m_grid->addWidget(row.value, r, 3);
        m_grid->addWidget(row.valueText, r, 4);
        m_grid->addWidget(row.flag, r, 5);
        m_rows.append(row);
    }

    const int perRow = 12;
    for (int b = 0; b < device->info.buttons.size(); ++b) {
        const QString label = device->info.kind == trainer::DeviceKind::Gamepad ? trainer::gamepadButtonLabel(b) : QString();
        auto* lamp = new ButtonLamp(label.isEmpty() ? QString::number(b) : label, this);
        lamp->setToolTip(tr("Button %1: %2").arg(b).arg(trainer::buttonName(device->info, b)));
        m_lampGrid->addWidget(lamp, b / perRow, b % perRow);
        m_lamps.append(lamp);
    }
    m_lampGrid->setColumnStretch(perRow, 1);
    m_buttonsTitle->setVisible(!m_lamps.isEmpty());
}

double ChannelPanel::rampSeconds(double filterHz)
{
    return filterHz > 0.0 ? kRampTimeConstants / (2.0 * std::numbers::pi * filterHz) : 0.0;
}

double ChannelPanel::rampFilterHz(double seconds)
{
    return seconds > 0.0 ? kRampTimeConstants / (2.0 * std::numbers::pi * seconds) : 0.0;
}

void ChannelPanel::setDevice(const trainer::DeviceState* device, const trainer::StationProfile& profile)
{
    const QString key = device ? QStringLiteral("%1|%2|%3|%4|%5")
                                     .arg(device->info.id, device->info.name)
                                     .arg(device->info.axes.size())
                                     .arg(device->info.buttons.size())
                                     .arg(device->replay)
                               : QString();
    if (key != m_key) {
        m_key = key;
        rebuild(device);
    }
    if (!device) return;

    const bool live = device->status == trainer::DeviceStatus::Connected;
    for (int a = 0; a < m_rows.size(); ++a) {
        const Row& row = m_rows[a];
        const trainer::ChannelCalibration c = channelCalibration(profile, device->info, a);
        const trainer::ChannelState ch =
            std::size_t(a) < device->channels.size() ? device->channels[std::size_t(a)] : trainer::ChannelState{};
        row.raw->setScale(c.rawMin, c.rawCentre, c.rawMax);
        row.raw->setValue(ch.raw);
        row.rawText->setText(formatRaw(ch.raw));
        row.value->setValue(ch.value);
        row.value->setFillColor(live ? QColor(0x1e, 0x88, 0xe5) : QColor(0xb0, 0xbe, 0xc5));
        row.valueText->setText(formatValue(ch.value));
        if (row.ramp && !row.ramp->hasFocus()) {
            m_filling = true;
            row.ramp->setValue(rampSeconds(c.filterHz));
            m_filling = false;
        }
        QString flag, tip;
        QColor color;
        if (ch.outOfRange) {
            flag = tr("out of range");
            tip = tr("The reading is beyond the calibrated range: the pot slipped, a wire is loose, or the "
                     "calibration is stale. Calibrate again.");
            color = redColor();
        } else if (!ch.calibrated) {
            flag = tr("not calibrated");
            tip = tr("The device's nominal range is in use until this channel is calibrated");
            color = amberColor();
        }
        row.flag->setText(flag);
        row.flag->setToolTip(tip);
        row.flag->setStyleSheet(flag.isEmpty() ? QString()
                                               : QStringLiteral("QLabel { color: white; background: %1; "
                                                                "border-radius: 3px; padding: 1px 6px; }")
                                                     .arg(color.name()));
    }
    for (int b = 0; b < m_lamps.size(); ++b)
        m_lamps[b]->setOn(std::size_t(b) < device->buttons.size() && device->buttons[std::size_t(b)] && live);
}

}  // namespace studio
