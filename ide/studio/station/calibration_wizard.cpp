#include "ide/studio/station/calibration_wizard.h"

#include "ide/studio/station/channel_bars.h"
#include "ide/studio/station/curve_plot.h"
#include "ide/studio/station/live_state.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <functional>

namespace studio {

namespace {

/// A wizard page whose completeness and set-up are the wizard's.
class FunctionPage : public QWizardPage {
public:
    std::function<bool()> complete;
    std::function<void()> enter;
    bool isComplete() const override { return complete ? complete() : true; }
    void initializePage() override
    {
        if (enter) enter();
    }
};

QLabel* instruction(QWidget* parent)
{
    auto* l = new QLabel(parent);
    l->setWordWrap(true);
    QFont f = l->font();
    f.setPointSizeF(f.pointSizeF() * 1.15);
    l->setFont(f);
    return l;
}

QLabel* connectionLabel(QWidget* parent)
{
    auto* l = new QLabel(parent);
    l->setWordWrap(true);
    l->setStyleSheet(QStringLiteral("color: %1").arg(redColor().name()));
    l->hide();
    return l;
}

}  // namespace

CalibrationWizard::CalibrationWizard(trainer::Station* station, const trainer::DeviceInfo& device, bool replay,
                                     int axis, const trainer::ChannelCalibration& current, const QString& match,
                                     QWidget* parent)
    : QWizard(parent), m_station(station), m_device(device), m_replay(replay), m_axis(axis), m_base(current)
{
    m_texts.add([this] {
        const QString axisName = m_axis >= 0 && m_axis < m_device.axes.size() ? m_device.axes[m_axis].name
                                                                               : tr("Axis %1").arg(m_axis);
        setWindowTitle(tr("Calibrate %1 of %2").arg(axisName, m_device.name));
        // the wizard's own buttons, in the language whether or not Qt's catalogue is installed
        setButtonText(QWizard::BackButton, tr("< &Back"));
        setButtonText(QWizard::NextButton, tr("&Next >"));
        setButtonText(QWizard::FinishButton, tr("&Finish"));
        setButtonText(QWizard::CancelButton, tr("Cancel"));
    });
    setWizardStyle(QWizard::ClassicStyle);
    setOption(QWizard::NoBackButtonOnStartPage);
    setPage(RestPage, buildRestPage());
    setPage(TravelPage, buildTravelPage());
    setPage(SettingsPage, buildSettingsPage());
    setStartId(RestPage);

    // where to keep it: an existing entry's key, else the kind for gamepads
    const QString kind = trainer::kindKey(device.kind);
    const QString key = match.isEmpty() ? (device.kind == trainer::DeviceKind::Gamepad ? kind : device.id) : match;
    (key == kind ? m_anyKind : m_thisDevice)->setChecked(true);

    m_timer = new QTimer(this);
    m_timer->setInterval(int(1000.0 / kRefreshHz));
    connect(m_timer, &QTimer::timeout, this, &CalibrationWizard::readStation);
    if (m_station) m_timer->start();
    connect(this, &QWizard::currentIdChanged, this, [this] {
        showRest();
        showTravel();
        showSettings();
    });
    resize(760, 520);
}

CalibrationWizard::~CalibrationWizard() = default;

double CalibrationWizard::nominalSpan() const
{
    if (m_axis >= 0 && m_axis < m_device.axes.size()) {
        const trainer::AxisInfo& a = m_device.axes[m_axis];
        if (std::isfinite(a.rawMax - a.rawMin) && a.rawMax > a.rawMin) return a.rawMax - a.rawMin;
    }
    return m_base.rawMax - m_base.rawMin;
}

QWizardPage* CalibrationWizard::buildRestPage()
{
    auto* page = new FunctionPage;
    page->complete = [this] { return m_capture.restCount() >= m_restReadings; };
    page->enter = [this] { restartRest(); };
    auto* layout = new QVBoxLayout(page);
    auto* text = instruction(page);
    layout->addWidget(text);
    m_connection[RestPage] = connectionLabel(page);
    layout->addWidget(m_connection[RestPage]);
    layout->addSpacing(8);
    m_restBar = new LevelBar(page);
    m_restBar->setFixedHeight(22);
    layout->addWidget(m_restBar);
    m_restProgress = new QProgressBar(page);
    layout->addWidget(m_restProgress);
    m_restText = new QLabel(page);
    m_restText->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_restText);
    m_restNoise = new QLabel(page);
    m_restNoise->setWordWrap(true);
    m_restNoise->setStyleSheet(QStringLiteral("color: %1").arg(amberColor().name()));
    m_restNoise->hide();
    layout->addWidget(m_restNoise);
    auto* again = new QPushButton(page);
    m_texts.add([page, text, again] {
        page->setTitle(tr("Leave the lever at rest"));
        text->setText(tr("Let go of the lever (or stick) and leave it where it rests by itself. Its reading over "
                         "the next moments is the centre of the channel."));
        again->setText(tr("Capture again"));
        again->setToolTip(tr("Forget these readings and capture the rest position anew"));
    });
    connect(again, &QPushButton::clicked, this, &CalibrationWizard::restartRest);
    auto* row = new QHBoxLayout;
    row->addWidget(again);
    row->addStretch(1);
    layout->addLayout(row);
    layout->addStretch(1);
    return page;
}

QWizardPage* CalibrationWizard::buildTravelPage()
{
    auto* page = new FunctionPage;
    page->complete = [this] { return m_capture.complete(nominalSpan()); };
    page->enter = [this] {
        m_capture.startTravel();
        m_phase = Phase::Travel;
        showTravel();
    };
    auto* layout = new QVBoxLayout(page);
    auto* text = instruction(page);
    layout->addWidget(text);
    m_connection[TravelPage] = connectionLabel(page);
    layout->addWidget(m_connection[TravelPage]);
    layout->addSpacing(8);
    m_travelBar = new LevelBar(page);
    m_travelBar->setFixedHeight(28);
    m_texts.add([this, page, text] {
        page->setTitle(tr("Move the lever to its full travel, both ways"));
        text->setText(tr("Push the lever slowly all the way to one end, then all the way to the other, and let it "
                         "come back to rest. A lever that only moves one way (a trigger, a pedal) is fine: move it "
                         "to its end."));
        m_travelBar->setToolTip(tr("The reading now; the red marks are the farthest seen each way"));
    });
    layout->addWidget(m_travelBar);
    m_travelText = new QLabel(page);
    m_travelText->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_travelText);
    m_travelWhy = new QLabel(page);
    m_travelWhy->setWordWrap(true);
    layout->addWidget(m_travelWhy);
    layout->addStretch(1);
    return page;
}

QWizardPage* CalibrationWizard::buildSettingsPage()
{
    auto* page = new FunctionPage;
    page->enter = [this] {
        m_phase = Phase::None;
        m_previewFilter.reset();
        showSettings();
    };
    auto* layout = new QHBoxLayout(page);

    auto* left = new QVBoxLayout;
    m_captured = new QLabel(page);
    m_captured->setWordWrap(true);
    m_captured->setTextInteractionFlags(Qt::TextSelectableByMouse);
    left->addWidget(m_captured);
    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
    auto percentSpin = [&] {
        auto* s = new QDoubleSpinBox(page);
        s->setRange(0.0, 100.0 * trainer::ChannelCalibration::kMaxDeadBand);
        s->setDecimals(1);
        s->setSingleStep(1.0);
        s->setSuffix(QStringLiteral(" %"));
        return s;
    };
    m_deadLow = percentSpin();
    m_deadHigh = percentSpin();
    m_deadLow->setValue(100.0 * m_base.deadBandLow);
    m_deadHigh->setValue(100.0 * m_base.deadBandHigh);
    form->addRow(QStringLiteral("-"), m_deadLow);
    form->addRow(QStringLiteral("-"), m_deadHigh);
    m_inverted = new QCheckBox(page);
    m_inverted->setChecked(m_base.inverted);
    form->addRow(QString(), m_inverted);
    m_curve = new QComboBox(page);
    m_curve->addItem(QString(), int(trainer::ResponseCurve::Linear));
    m_curve->addItem(QString(), int(trainer::ResponseCurve::Exponential));
    m_curve->setCurrentIndex(m_base.curve == trainer::ResponseCurve::Exponential ? 1 : 0);
    form->addRow(QStringLiteral("-"), m_curve);
    m_exponent = new QDoubleSpinBox(page);
    m_exponent->setRange(trainer::ChannelCalibration::kMinExponent, trainer::ChannelCalibration::kMaxExponent);
    m_exponent->setDecimals(2);
    m_exponent->setSingleStep(0.25);
    m_exponent->setValue(m_base.exponent);
    form->addRow(QStringLiteral("-"), m_exponent);
    m_filter = new QDoubleSpinBox(page);
    m_filter->setRange(0.0, 200.0);
    m_filter->setDecimals(1);
    m_filter->setSingleStep(1.0);
    m_filter->setValue(m_base.filterHz);
    form->addRow(QStringLiteral("-"), m_filter);
    left->addLayout(form);

    auto* keep = new QGroupBox(page);
    auto* keepLayout = new QVBoxLayout(keep);
    m_thisDevice = new QRadioButton(keep);
    m_anyKind = new QRadioButton(keep);
    const auto label = [form](QWidget* field) { return qobject_cast<QLabel*>(form->labelForField(field)); };
    m_texts.add([=, this] {
        page->setTitle(tr("Dead band, direction and response"));
        m_deadLow->setToolTip(tr("Fraction of the travel below the centre where the output stays 0"));
        m_deadHigh->setToolTip(tr("Fraction of the travel above the centre where the output stays 0"));
        label(m_deadLow)->setText(tr("Dead band below centre:"));
        label(m_deadHigh)->setText(tr("Dead band above centre:"));
        m_inverted->setText(tr("Inverted"));
        m_inverted->setToolTip(tr("Pushing the lever towards its maximum reading gives a negative command"));
        m_curve->setItemText(0, tr("Linear"));
        m_curve->setItemText(1, tr("Exponential"));
        m_curve->setToolTip(tr("Exponential: finer control near the centre"));
        label(m_curve)->setText(tr("Response:"));
        m_exponent->setToolTip(tr("k of y = (e^(k·x) − 1)/(e^k − 1): larger is finer near the centre"));
        label(m_exponent)->setText(tr("Curve parameter k:"));
        m_filter->setSuffix(tr(" Hz"));
        m_filter->setSpecialValueText(tr("off"));
        m_filter->setToolTip(tr("Low-pass cutoff frequency against a noisy pot (0: no filter)"));
        label(m_filter)->setText(tr("Low-pass filter:"));
        keep->setTitle(tr("Keep this calibration for"));
        m_thisDevice->setText(tr("This device only (%1)").arg(m_device.id));
        m_thisDevice->setToolTip(tr("Only this very device uses it"));
        m_anyKind->setText(tr("Any %1").arg(trainer::kindName(m_device.kind).toLower()));
        m_anyKind->setToolTip(tr("Every device of this kind uses it, so the profile works with another one of the "
                                 "same make (profile key “%1”)")
                                  .arg(trainer::kindKey(m_device.kind)));
    });
    auto* group = new QButtonGroup(keep);
    group->addButton(m_thisDevice);
    group->addButton(m_anyKind);
    keepLayout->addWidget(m_thisDevice);
    keepLayout->addWidget(m_anyKind);
    left->addWidget(keep);
    left->addStretch(1);
    layout->addLayout(left, 0);

    auto* right = new QVBoxLayout;
    m_plot = new CurvePlot(page);
    right->addWidget(m_plot, 1);
    auto* bars = new QFormLayout;
    m_previewRaw = new LevelBar(page);
    m_previewValue = new LevelBar(page);
    m_previewValue->setScale(-1.0, 0.0, 1.0);
    bars->addRow(QStringLiteral("-"), m_previewRaw);
    bars->addRow(QStringLiteral("-"), m_previewValue);
    m_texts.add([bars, this] {
        qobject_cast<QLabel*>(bars->labelForField(m_previewRaw))->setText(tr("Raw:"));
        qobject_cast<QLabel*>(bars->labelForField(m_previewValue))->setText(tr("Calibrated:"));
    });
    right->addLayout(bars);
    m_previewText = new QLabel(page);
    right->addWidget(m_previewText);
    layout->addLayout(right, 1);

    for (QDoubleSpinBox* s : {m_deadLow, m_deadHigh, m_exponent, m_filter})
        connect(s, &QDoubleSpinBox::valueChanged, this, &CalibrationWizard::settingsChanged);
    connect(m_inverted, &QCheckBox::toggled, this, &CalibrationWizard::settingsChanged);
    connect(m_curve, &QComboBox::currentIndexChanged, this, &CalibrationWizard::settingsChanged);
    return page;
}

void CalibrationWizard::setLiveInput(bool live)
{
    if (live && m_station) m_timer->start();
    else m_timer->stop();
}

bool CalibrationWizard::liveInput() const
{
    return m_timer->isActive();
}

void CalibrationWizard::setRestReadings(int count)
{
    m_restReadings = std::max(1, count);
    showRest();
    if (auto* p = page(RestPage)) emit p->completeChanged();
}

void CalibrationWizard::restartRest()
{
    m_capture.startRest();
    m_phase = Phase::Rest;
    showRest();
    if (auto* p = page(RestPage)) emit p->completeChanged();
}

void CalibrationWizard::readStation()
{
    const auto state = stationState(m_station);
    const trainer::DeviceState* d = state ? findDevice(*state, m_device.id, m_replay) : nullptr;
    QString problem;
    if (!d) problem = tr("%1 is not there any more.").arg(m_device.name);
    else if (d->status != trainer::DeviceStatus::Connected)
        problem = tr("%1: %2 — waiting for it.")
                      .arg(m_device.name, d->statusText.isEmpty() ? statusName(d->status) : d->statusText);
    else if (std::size_t(m_axis) >= d->channels.size())
        problem = tr("%1 has no channel %2.").arg(m_device.name).arg(m_axis);
    for (QLabel* l : m_connection) {
        if (!l) continue;
        l->setText(problem);
        l->setVisible(!problem.isEmpty());
    }
    if (problem.isEmpty()) addReading(d->channels[std::size_t(m_axis)].raw);
}

void CalibrationWizard::addReading(double raw)
{
    m_last = raw;
    switch (currentId()) {
    case RestPage:
        if (m_phase == Phase::Rest && m_capture.restCount() < m_restReadings) {
            m_capture.add(raw);
            emit page(RestPage)->completeChanged();
        }
        showRest();
        break;
    case TravelPage:
        if (m_phase == Phase::Travel) {
            m_capture.add(raw);
            emit page(TravelPage)->completeChanged();
        }
        showTravel();
        break;
    case SettingsPage: {
        const trainer::ChannelCalibration c = calibration();
        m_previewOutput = m_previewFilter.update(c.apply(raw), c.filterHz, 1.0 / kRefreshHz);
        showSettings();
        break;
    }
    default: break;
    }
}

trainer::ChannelCalibration CalibrationWizard::calibration() const
{
    trainer::ChannelCalibration c = m_capture.result(m_base);
    c.deadBandLow = m_deadLow->value() / 100.0;
    c.deadBandHigh = m_deadHigh->value() / 100.0;
    c.inverted = m_inverted->isChecked();
    c.curve = m_curve->currentData().toInt() == int(trainer::ResponseCurve::Exponential)
                  ? trainer::ResponseCurve::Exponential
                  : trainer::ResponseCurve::Linear;
    c.exponent = m_exponent->value();
    c.filterHz = m_filter->value();
    return c;
}

QString CalibrationWizard::deviceMatch() const
{
    return m_anyKind->isChecked() ? trainer::kindKey(m_device.kind) : m_device.id;
}

void CalibrationWizard::showRest()
{
    if (currentId() != RestPage) return;
    double lo = m_base.rawMin, rest = m_base.rawCentre, hi = m_base.rawMax;
    if (m_axis >= 0 && m_axis < m_device.axes.size()) {
        lo = m_device.axes[m_axis].rawMin;
        rest = m_device.axes[m_axis].rawRest;
        hi = m_device.axes[m_axis].rawMax;
    }
    const double reading = std::isfinite(m_last) ? m_last : rest;
    m_restBar->setScale(std::min(lo, reading), rest, std::max(hi, reading));
    m_restBar->setValue(reading);
    m_restProgress->setRange(0, m_restReadings);
    m_restProgress->setValue(std::min(m_capture.restCount(), m_restReadings));
    const bool done = m_capture.restCount() >= m_restReadings;
    m_restProgress->setFormat(done ? tr("Captured") : tr("Capturing… %p%"));
    if (m_capture.restCount() == 0) {
        m_restText->setText(std::isfinite(m_last) ? tr("Reading: %1").arg(formatRaw(m_last)) : tr("Waiting for readings…"));
    } else {
        const double spread = m_capture.restSpread();
        const double span = nominalSpan();
        m_restText->setText(tr("Reading: %1    Centre: %2    Spread: %3 (%4 % of the travel)")
                                .arg(formatRaw(m_last), formatNumber(m_capture.centre()), formatRaw(spread),
                                     QLocale().toString(span > 0 ? 100.0 * spread / span : 0.0, 'f', 1)));
        const bool noisy = span > 0 && spread > kNoisySpread * span;
        m_restNoise->setText(noisy ? tr("The reading moves while the lever rests: a noisy pot or a loose wire? A "
                                        "dead band or the low-pass filter will hide some of it.")
                                   : QString());
        m_restNoise->setVisible(noisy);
    }
}

void CalibrationWizard::showTravel()
{
    if (currentId() != TravelPage) return;
    double lo = m_base.rawMin, hi = m_base.rawMax;
    if (m_axis >= 0 && m_axis < m_device.axes.size()) {
        lo = m_device.axes[m_axis].rawMin;
        hi = m_device.axes[m_axis].rawMax;
    }
    const double centre = m_capture.centre();
    const double reading = std::isfinite(m_last) ? m_last : centre;
    const double seenLo = m_capture.seenMin(), seenHi = m_capture.seenMax();
    lo = std::min({lo, seenLo, reading});
    hi = std::max({hi, seenHi, reading});
    m_travelBar->setScale(lo, std::clamp(centre, lo, hi), hi);
    m_travelBar->setValue(reading);
    m_travelBar->setMarks(seenLo, seenHi);
    m_travelText->setText(tr("Reading: %1    Centre: %2    Seen: %3 … %4")
                              .arg(formatRaw(reading), formatNumber(centre), formatRaw(seenLo), formatRaw(seenHi)));
    QString why;
    const bool complete = m_capture.complete(nominalSpan(), &why);
    m_travelWhy->setText(complete ? tr("Enough travel seen. Keep moving to reach the very ends, then press Next.") : why);
    m_travelWhy->setStyleSheet(complete ? QStringLiteral("color: %1").arg(statusColor(trainer::DeviceStatus::Connected).name())
                                        : QString());
}

void CalibrationWizard::showSettings()
{
    if (currentId() != SettingsPage) return;
    const trainer::ChannelCalibration c = calibration();
    QString captured = tr("Captured: minimum %1, centre %2, maximum %3.")
                           .arg(formatRaw(c.rawMin), formatNumber(c.rawCentre), formatRaw(c.rawMax));
    if (c.rawCentre == c.rawMin || c.rawCentre == c.rawMax)
        captured += QLatin1Char(' ') + tr("One-sided: the output goes from 0 to 1.");
    m_captured->setText(captured);
    m_exponent->setEnabled(c.curve == trainer::ResponseCurve::Exponential);
    // a one-sided channel has no travel on the other side of its centre
    m_deadLow->setEnabled(c.rawCentre > c.rawMin);
    m_deadHigh->setEnabled(c.rawCentre < c.rawMax);
    m_plot->setCalibration(c);
    m_plot->setReading(m_last);
    if (c.isValid()) {
        const auto [bandLo, bandHi] = CurvePlot::deadBand(c);
        m_previewRaw->setScale(c.rawMin, c.rawCentre, c.rawMax);
        m_previewRaw->setBand(bandLo, bandHi);
    }
    m_previewRaw->setValue(std::isfinite(m_last) ? m_last : c.rawCentre);
    m_previewValue->setValue(m_previewOutput);
    m_previewText->setText(tr("Raw %1 → %2").arg(formatRaw(m_last), formatValue(m_previewOutput)));
}

void CalibrationWizard::settingsChanged()
{
    if (std::isfinite(m_last)) {
        // the preview follows the new settings at once (the filter restarts)
        m_previewFilter.reset();
        const trainer::ChannelCalibration c = calibration();
        m_previewOutput = m_previewFilter.update(c.apply(m_last), c.filterHz, 1.0 / kRefreshHz);
    }
    showSettings();
}

void CalibrationWizard::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        setLocale(QLocale());  // the spin boxes in the new locale (a window: its own)
        m_texts.apply();
        showRest();
        showTravel();
        showSettings();
    }
    QWizard::changeEvent(event);
}

void CalibrationWizard::accept()
{
    emit calibrationReady(deviceMatch(), m_axis, calibration());
    QWizard::accept();
}

}  // namespace studio
