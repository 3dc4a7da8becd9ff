#include "ide/studio/dialogs/inertia_dialog.h"

#include "ide/studio/dialogs/b_statement.h"
#include "ide/i18n/diagnostic_text.h"
#include "solver/spec/validate.h"
#include "solver/parse/parser.h"
#include "solver/parse/writer.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFile>
#include <QFileInfo>
#include <QFontDatabase>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QTextBlock>
#include <QTextCursor>
#include <QVBoxLayout>

#include <cmath>

namespace studio {

namespace {

/// A B statement's start, its body id captured: "B 3 …", "b 3 // …".
const QRegularExpression& bStatementPattern()
{
    static const QRegularExpression re(QStringLiteral("^\\s*[Bb][ \\t]+(\\d+)(?=[ \\t]|$|//|#)"));
    return re;
}

// numbers in the table's model text and in B lines are the model language's ('.'); the
// results a person reads are in the current locale (shown())
QString num(double v) { return QString::fromStdString(solver::parse::formatNumber(v)); }

/// A computed value as a person reads it: 6 significant digits in the current locale
/// (1,5 in Spanish), without group separators.
QString shown(double v)
{
    if (v == 0) return QStringLiteral("0");
    QLocale l;
    l.setNumberOptions(l.numberOptions() | QLocale::OmitGroupSeparator);
    return l.toString(v, 'g', 6);
}

QString vec(const Eigen::Vector3d& v) { return QStringLiteral("%1 %2 %3").arg(num(v.x()), num(v.y()), num(v.z())); }

/// A string token of the model language: quotes, with \" and \\ escaped.
QString quotedString(const std::string& s)
{
    QString q = QString::fromStdString(s);
    q.replace(QLatin1Char('\\'), QStringLiteral("\\\\"));
    q.replace(QLatin1Char('"'), QStringLiteral("\\\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

/// Signed relative difference in percent, "+1.25 %", or "n/a" when the file has 0.
QString relative(double computed, double written)
{
    if (written == 0) return computed == 0 ? InertiaDialog::tr("%1 %").arg(0) : InertiaDialog::tr("n/a (file: 0)");
    QLocale l;
    l.setNumberOptions(l.numberOptions() | QLocale::OmitGroupSeparator);
    const QString value = l.toString(100.0 * (computed - written) / std::abs(written), 'f', 2);
    return InertiaDialog::tr("%1 %").arg(computed >= written ? QStringLiteral("+") + value : value);
}

QTableWidgetItem* readOnly(const QString& text)
{
    auto* item = new QTableWidgetItem(text);
    item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    return item;
}

}  // namespace

InertiaDialog::InertiaDialog(std::shared_ptr<const ModelBundle> bundle, QWidget* parent)
    : QDialog(parent), m_bundle(std::move(bundle))
{
    if (m_bundle) {
        m_spec = std::shared_ptr<const solver::ModelSpec>(m_bundle->compiled, &m_bundle->compiled->spec);
        m_filePath = m_bundle->filePath;
    } else {
        m_spec = std::make_shared<solver::ModelSpec>();
    }
    build();
}

InertiaDialog::InertiaDialog(const solver::ModelSpec& spec, const QString& filePath, QWidget* parent)
    : QDialog(parent), m_spec(std::make_shared<solver::ModelSpec>(spec)), m_filePath(filePath)
{
    build();
}

InertiaDialog::~InertiaDialog() = default;

void InertiaDialog::build()
{
    // (the texts: retranslate())
    if (!m_filePath.isEmpty()) m_modelDir = QFileInfo(m_filePath).absolutePath();
    // the file's text, until the editor's is given
    if (!m_filePath.isEmpty()) {
        QFile f(m_filePath);
        if (f.open(QIODevice::ReadOnly)) {
            setSourceText(QString::fromUtf8(f.readAll()));
        }
    }

    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    m_bodyLabel = new QLabel(this);
    top->addWidget(m_bodyLabel);
    m_body = new QComboBox(this);
    m_body->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_bodyLabel->setBuddy(m_body);
    top->addWidget(m_body);
    top->addStretch(1);
    layout->addLayout(top);

    m_note = new QLabel(this);
    m_note->setWordWrap(true);
    QFont italic = m_note->font();
    italic.setItalic(true);
    m_note->setFont(italic);
    layout->addWidget(m_note);

    m_table = new QTableWidget(0, ColumnCount, this);
    for (int c = 0; c < ColumnCount; ++c) m_table->setHorizontalHeaderItem(c, new QTableWidgetItem);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(m_table, 1);

    m_errors = new QLabel(this);
    m_errors->setWordWrap(true);
    m_errors->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_errors->setStyleSheet(QStringLiteral("color: #b00020"));
    m_errors->hide();
    layout->addWidget(m_errors);

    m_results = new QGroupBox(this);
    auto* form = new QFormLayout(m_results);
    m_mass = new QLabel(m_results);
    m_com = new QLabel(m_results);
    m_tensor = new QTableWidget(3, 3, m_results);
    m_tensor->setHorizontalHeaderLabels({QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z")});
    m_tensor->setVerticalHeaderLabels({QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z")});
    m_tensor->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_tensor->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_tensor->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_tensor->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    m_tensor->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_tensor->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_principal = new QLabel(m_results);
    m_difference = new QLabel(m_results);
    for (QLabel* l : {m_mass, m_com, m_principal, m_difference}) l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    const auto addRow = [](QFormLayout* f, QLabel*& label, QWidget* field) {
        label = new QLabel(f->parentWidget());
        label->setBuddy(field);
        f->addRow(label, field);
    };
    addRow(form, m_massLabel, m_mass);
    addRow(form, m_comLabel, m_com);
    addRow(form, m_tensorLabel, m_tensor);
    addRow(form, m_principalLabel, m_principal);
    addRow(form, m_differenceLabel, m_difference);
    layout->addWidget(m_results);

    m_lines = new QGroupBox(this);
    auto* linesForm = new QFormLayout(m_lines);
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    m_fileB = new QLineEdit(m_lines);
    m_computedB = new QLineEdit(m_lines);
    for (QLineEdit* e : {m_fileB, m_computedB}) {
        e->setReadOnly(true);
        e->setFont(mono);
        e->setMinimumWidth(480);
    }
    addRow(linesForm, m_fileBLabel, m_fileB);
    addRow(linesForm, m_computedBLabel, m_computedB);
    layout->addWidget(m_lines);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_replace = buttons->addButton(QString(), QDialogButtonBox::ActionRole);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_replace, &QPushButton::clicked, this, [this] {
        if (m_result) emit bLineReady(bodyId(), m_bLine, bStatementLine());
    });
    layout->addWidget(buttons);

    connect(m_table, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
        if (m_loading || item->column() == MassColumn) return;
        m_table->resizeColumnToContents(item->column());  // a longer value stays readable
        recompute();
    });
    connect(m_body, &QComboBox::currentIndexChanged, this, [this] { loadSolids(); });
    retranslateStatic();
    fillBodies();
    resize(980, 720);
}

void InertiaDialog::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange && m_table) {
        retranslateStatic();
        // the bodies, the solids' labels and the results (the edits in the table stay)
        for (int k = 0; k < m_body->count(); ++k) m_body->setItemText(k, bodyText(m_body->itemData(k).toInt()));
        {
            const QSignalBlocker block(m_table);
            for (int r = 0; r < m_table->rowCount(); ++r) retranslateRow(r);
        }
        recompute();
    } else if (event->type() == QEvent::LocaleChange && m_table) {
        recompute();  // (the numbers a person reads)
    }
    QDialog::changeEvent(event);
}

void InertiaDialog::retranslateStatic()
{
    setWindowTitle(tr("Inertia calculator"));
    m_bodyLabel->setText(tr("Body:"));
    m_note->setText(tr("The solids of a body are its graphics (G) with MASS or RHO. Edits in this table only change "
                       "this calculation: the G lines in the file are not changed. Only the body's B line can be "
                       "written back, with the button below."));
    const QStringList headers{tr("Graphic"), tr("Shape"), tr("Dimensions [m]"), tr("POS [m]"), tr("AXIS"),
                              tr("ROT [axis, °]"), tr("Density or mass"), tr("Value"), tr("Solid's mass [kg]")};
    for (int c = 0; c < ColumnCount; ++c) m_table->horizontalHeaderItem(c)->setText(headers[c]);
    m_table->horizontalHeaderItem(ShapeColumn)->setToolTip(tr("BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM or MESH"));
    m_table->horizontalHeaderItem(DimsColumn)
        ->setToolTip(tr("BOX X Y Z; CYL R L; TUBE RO RI L; SPHERE R; CONE R L; ELLIPSOID A B C; PRISM H x1 y1 x2 y2 …; "
                        "MESH \"file\" [SCALE s]"));
    m_table->horizontalHeaderItem(ValueColumn)->setToolTip(tr("RHO in kg/m³, or MASS in kg"));
    m_results->setTitle(tr("Computed (body axes, about the centre of mass)"));
    m_massLabel->setText(tr("Mass:"));
    m_comLabel->setText(tr("Centre of mass:"));
    m_tensorLabel->setText(tr("Inertia tensor [kg·m²]:"));
    m_tensor->setToolTip(tr("I = [[Ixx Ixy Ixz] [Ixy Iyy Iyz] [Ixz Iyz Izz]], Ixy = −∫xy dm"));
    m_principalLabel->setText(tr("Principal moments:"));
    m_differenceLabel->setText(tr("Against the file:"));
    m_lines->setTitle(tr("B line"));
    m_fileBLabel->setText(tr("In the file:"));
    m_computedBLabel->setText(tr("Computed:"));
    m_replace->setText(tr("Replace B line in editor"));
    m_replace->setToolTip(tr("Writes the computed B line into the editor (one undo step); the G lines stay as they are"));
}

QString InertiaDialog::bodyText(int id) const
{
    const solver::BodySpec* b = m_spec->body(id);
    if (!b) return tr("B %1").arg(id);
    int solids = 0;
    for (const solver::GraphicSpec& g : m_spec->graphics) solids += g.body == b->id && (g.mass || g.rho);
    const QString name = QString::fromStdString(b->name);
    if (solids == 0)
        return name.isEmpty() ? tr("B %1 (no solids)").arg(id) : tr("B %1  %2 (no solids)").arg(QString::number(id), name);
    return name.isEmpty() ? tr("B %1 (solids: %2)").arg(id).arg(solids)
                          : tr("B %1  %2 (solids: %3)").arg(QString::number(id), name, QString::number(solids));
}

void InertiaDialog::retranslateRow(int r)
{
    QTableWidgetItem* idItem = m_table->item(r, IdColumn);
    const int g = idItem->data(Qt::UserRole).toInt();
    idItem->setText(tr("G %1").arg(g));
    const int line = idItem->data(LineRole).toInt();
    idItem->setToolTip(line > 0 ? tr("line %1").arg(line) : QString());
    if (auto* kind = qobject_cast<QComboBox*>(m_table->cellWidget(r, KindColumn))) {
        kind->setItemText(0, tr("RHO [kg/m³]"));
        kind->setItemText(1, tr("MASS [kg]"));
    }
}

void InertiaDialog::setSourceText(const QString& text)
{
    m_sourceLines = text.split(QLatin1Char('\n'));
    for (QString& l : m_sourceLines) {
        if (l.endsWith(QLatin1Char('\r'))) l.chop(1);
    }
    m_haveSource = true;
    if (m_table) recompute();
}

QString InertiaDialog::sourceLine(int line) const
{
    if (!m_haveSource || line < 1 || line > m_sourceLines.size()) return {};
    return m_sourceLines[line - 1];
}

int InertiaDialog::bodyLine(const solver::BodySpec& body) const
{
    // the model's line, unless the text changed under it (a Replace added a B line, an
    // edit moved it): then the body's B statement wherever it is now
    const QRegularExpression& bStatement = bStatementPattern();
    const auto isOwn = [&](const QString& text) {
        const QRegularExpressionMatch m = bStatement.match(text);
        return m.hasMatch() && m.captured(1).toInt() == body.id;
    };
    const int line = body.src.pos.valid() ? body.src.pos.line : -1;
    if (!m_haveSource || isOwn(sourceLine(line))) return line;
    for (int i = 0; i < m_sourceLines.size(); ++i) {
        if (isOwn(m_sourceLines[i])) return i + 1;
    }
    return line;
}

void InertiaDialog::fillBodies()
{
    const QSignalBlocker block(m_body);
    m_body->clear();
    int first = -1;
    for (const solver::BodySpec& b : m_spec->bodies) {
        if (b.id == 0) continue;
        int solids = 0;
        for (const solver::GraphicSpec& g : m_spec->graphics) solids += g.body == b.id && (g.mass || g.rho);
        m_body->addItem(bodyText(b.id), b.id);
        if (solids && first < 0) first = m_body->count() - 1;
    }
    m_body->setCurrentIndex(first >= 0 ? first : 0);
    loadSolids();
}

bool InertiaDialog::setBody(int id)
{
    const int k = m_body->findData(id);
    if (k < 0) return false;
    m_body->setCurrentIndex(k);  // loads the solids
    return true;
}

int InertiaDialog::bodyId() const { return m_body->currentIndex() >= 0 ? m_body->currentData().toInt() : -1; }

int InertiaDialog::bStatementLine() const
{
    const solver::BodySpec* b = m_spec->body(bodyId());
    return b ? bodyLine(*b) : -1;
}

void InertiaDialog::loadSolids()
{
    m_loading = true;
    m_table->setRowCount(0);
    const int id = bodyId();
    for (const solver::GraphicSpec& g : m_spec->graphics) {
        if (g.body != id || id == 0 || (!g.mass && !g.rho)) continue;
        const int r = m_table->rowCount();
        m_table->insertRow(r);
        auto* idItem = readOnly(QString());
        idItem->setData(Qt::UserRole, g.id);
        idItem->setData(LineRole, g.src.pos.valid() ? g.src.pos.line : 0);
        m_table->setItem(r, IdColumn, idItem);
        m_table->setItem(r, ShapeColumn, new QTableWidgetItem(QString::fromLatin1(solver::shapeKeyword(g.shape))));
        QString dims;
        if (g.shape == solver::ShapeKind::Mesh) {
            dims = quotedString(g.meshFile);
            if (g.hasScale) dims += QStringLiteral(" SCALE ") + num(g.scale);
        } else {
            QStringList parts;
            for (double d : g.dims) parts << num(d);
            dims = parts.join(QLatin1Char(' '));
        }
        m_table->setItem(r, DimsColumn, new QTableWidgetItem(dims));
        m_table->setItem(r, PosColumn, new QTableWidgetItem(g.hasPosition ? vec(g.position) : QStringLiteral("0 0 0")));
        m_table->setItem(r, AxisColumn, new QTableWidgetItem(g.hasAxis ? vec(g.axis) : QString()));
        m_table->setItem(r, RotColumn,
                         new QTableWidgetItem(g.hasRot ? vec(g.rotAxis) + QLatin1Char(' ') + num(g.rotDeg) : QString()));
        auto* kind = new QComboBox(m_table);
        kind->addItem(QString(), QStringLiteral("RHO"));
        kind->addItem(QString(), QStringLiteral("MASS"));
        kind->setCurrentIndex(g.rho ? 0 : 1);
        connect(kind, &QComboBox::currentIndexChanged, this, [this] { recompute(); });
        m_table->setCellWidget(r, KindColumn, kind);
        m_table->setItem(r, ValueColumn, new QTableWidgetItem(num(g.rho ? *g.rho : *g.mass)));
        m_table->setItem(r, MassColumn, readOnly(QString()));
        retranslateRow(r);
    }
    m_table->resizeColumnsToContents();
    m_table->horizontalHeader()->setStretchLastSection(false);  // (again: resizing to contents undid it)
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_loading = false;
    recompute();
}

void InertiaDialog::recompute()
{
    m_result.reset();
    m_statement.clear();
    m_bLine.clear();
    const int id = bodyId();
    const solver::BodySpec* body = m_spec->body(id);
    m_fileLine = body ? sourceLine(bodyLine(*body)).trimmed() : QString();
    if (body && m_fileLine.isEmpty()) m_fileLine = bstatement::fromSpec(*body);

    // the table as G statements, checked by the solver's parser and checks: line 1 is
    // the body, line r + 2 the table's row r
    QStringList text{QStringLiteral("B %1").arg(id)};
    for (int r = 0; r < m_table->rowCount(); ++r) {
        const auto cell = [&](int c) { return m_table->item(r, c) ? m_table->item(r, c)->text().trimmed() : QString(); };
        auto* kind = qobject_cast<QComboBox*>(m_table->cellWidget(r, KindColumn));
        QString g = QStringLiteral("G %1 B %2 %3 %4").arg(m_table->item(r, IdColumn)->data(Qt::UserRole).toInt()).arg(id).arg(cell(ShapeColumn), cell(DimsColumn));
        if (!cell(PosColumn).isEmpty()) g += QStringLiteral(" POS ") + cell(PosColumn);
        if (!cell(AxisColumn).isEmpty()) g += QStringLiteral(" AXIS ") + cell(AxisColumn);
        if (!cell(RotColumn).isEmpty()) g += QStringLiteral(" ROT ") + cell(RotColumn);
        g += QLatin1Char(' ') + (kind ? kind->currentData().toString() : QStringLiteral("RHO")) + QLatin1Char(' ') + cell(ValueColumn);
        text << g;
    }
    solver::Diagnostics diags(m_filePath.toStdString());
    solver::ModelSpec mini = solver::parse::parseModel(text.join(QLatin1Char('\n')).toStdString(), diags);
    mini.file = m_spec->file;
    if (!diags.hasErrors()) solver::validateModel(mini, diags, m_modelDir.toStdString());

    std::vector<solver::MassProperties> parts;
    std::vector<double> solidMass(static_cast<std::size_t>(m_table->rowCount()), std::nan(""));
    if (!diags.hasErrors()) {
        for (std::size_t k = 0; k < mini.graphics.size(); ++k) {
            parts.push_back(solver::solidMassProperties(mini.graphics[k], m_modelDir.toStdString(), diags));
            if (k < solidMass.size()) solidMass[k] = parts.back().mass;
        }
    }

    // the rows with problems
    QStringList messages;
    std::vector<char> bad(static_cast<std::size_t>(m_table->rowCount()), 0);
    for (const solver::Diagnostic& d : diags) {
        const int row = d.pos.line - 2;
        const QString message = i18n::message(d), hint = i18n::hint(d);
        if (d.severity == solver::Severity::Error && row >= 0 && row < m_table->rowCount()) bad[static_cast<std::size_t>(row)] = 1;
        const bool error = d.severity == solver::Severity::Error;
        if (hint.isEmpty()) messages << (error ? tr("Error: %1") : tr("Warning: %1")).arg(message);
        else messages << (error ? tr("Error: %1 — %2") : tr("Warning: %1 — %2")).arg(message, hint);
    }
    {
        const QSignalBlocker block(m_table);
        m_loading = true;
        for (int r = 0; r < m_table->rowCount(); ++r) {
            const bool isBad = bad[static_cast<std::size_t>(r)] != 0;
            for (int c = 0; c < ColumnCount; ++c) {
                if (QTableWidgetItem* item = m_table->item(r, c)) item->setBackground(isBad ? QColor(255, 220, 220) : QBrush());
            }
            const double sm = solidMass[static_cast<std::size_t>(r)];
            m_table->item(r, MassColumn)->setText(std::isfinite(sm) && !diags.hasErrors() ? shown(sm) : QString());
        }
        m_loading = false;
    }
    if (m_table->rowCount() == 0) {
        messages << tr("Body %1 has no solids: give some of its graphics MASS or RHO (e.g. G 1 B %1 BOX 0.2 0.2 0.2 RHO 7850).").arg(id);
    } else if (!diags.hasErrors()) {
        const solver::MassProperties total = solver::combine(parts);
        if (total.mass > 0) {
            m_result = total;
        } else {
            messages << tr("The solids have no mass.");
        }
    }
    m_errors->setText(messages.join(QLatin1Char('\n')));
    m_errors->setVisible(!messages.isEmpty());

    if (m_result) {
        m_statement = bstatement::format(id, *m_result);
        const QString line = body ? sourceLine(bodyLine(*body)) : QString();
        m_bLine = line.isEmpty() ? QString() : bstatement::replaceInLine(line, m_statement);
        if (m_bLine.isEmpty()) {
            const QString name = body ? bstatement::nameToken(body->name) : QString();
            m_bLine = name.isEmpty() ? m_statement : m_statement + QLatin1Char(' ') + name;
        }
    }
    showResult();
}

void InertiaDialog::showResult()
{
    m_fileB->setText(m_fileLine);
    m_computedB->setText(m_bLine);
    for (QLineEdit* e : {m_fileB, m_computedB}) e->setCursorPosition(0);  // the start of a long line: "B id m …"
    m_replace->setEnabled(m_result.has_value());
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            QString t = m_result ? shown(m_result->inertia(r, c)) : QStringLiteral("—");
            if (!m_tensor->item(r, c)) m_tensor->setItem(r, c, new QTableWidgetItem);
            m_tensor->item(r, c)->setText(t);
            m_tensor->item(r, c)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        }
    }
    if (!m_result) {
        for (QLabel* l : {m_mass, m_com, m_principal, m_difference}) l->setText(QStringLiteral("—"));
        return;
    }
    const solver::MassProperties& p = *m_result;
    m_mass->setText(tr("%1 kg").arg(shown(p.mass)));
    m_com->setText(tr("(%1, %2, %3) m")
                       .arg(shown(p.com.x()), shown(p.com.y()), shown(p.com.z())));
    const solver::PrincipalAxes pa = solver::principalAxes(p.inertia);
    m_principal->setText(tr("%1, %2, %3 kg·m²")
                             .arg(shown(pa.moments.x()), shown(pa.moments.y()),
                                  shown(pa.moments.z())));
    QStringList axes;
    for (int c = 0; c < 3; ++c) {
        axes << tr("%1 kg·m² about (%2, %3, %4)")
                    .arg(shown(pa.moments[c]), shown(pa.axes(0, c)), shown(pa.axes(1, c)),
                         shown(pa.axes(2, c)));
    }
    m_principal->setToolTip(axes.join(QLatin1Char('\n')));
    const solver::BodySpec* body = m_spec->body(bodyId());
    if (body && body->hasMass) {
        m_difference->setText(tr("m %1, Ixx %2, Iyy %3, Izz %4")
                                  .arg(relative(p.mass, body->mass), relative(p.inertia(0, 0), body->inertia.x()),
                                       relative(p.inertia(1, 1), body->inertia.y()), relative(p.inertia(2, 2), body->inertia.z())));
    } else {
        m_difference->setText(tr("the file's B line has no mass"));
    }
}

QString InertiaDialog::errorText() const { return m_errors->isHidden() ? QString() : m_errors->text(); }

void InertiaDialog::applyBLine(QPlainTextEdit* editor, int line, const QString& text)
{
    if (!editor) return;
    QTextDocument* doc = editor->document();
    // the body's id, to check that `line` still holds its B statement (the text may have
    // changed since the model was loaded)
    const QRegularExpression& bStatement = bStatementPattern();
    const QRegularExpressionMatch own = bStatement.match(text);
    const QString id = own.hasMatch() ? own.captured(1) : QString();
    const auto isOwn = [&](const QTextBlock& b) {
        const QRegularExpressionMatch m = bStatement.match(b.text());
        return m.hasMatch() && !id.isEmpty() && m.captured(1).toInt() == id.toInt();
    };
    QTextBlock target;
    if (line >= 1 && line <= doc->blockCount()) {
        target = doc->findBlockByNumber(line - 1);
        if (!id.isEmpty() && !isOwn(target)) target = QTextBlock();
    }
    QTextBlock lastB;
    for (QTextBlock b = doc->begin(); b.isValid(); b = b.next()) {
        if (!bStatement.match(b.text()).hasMatch()) continue;
        lastB = b;
        if (!target.isValid() && line >= 1 && isOwn(b)) target = b;  // the statement moved
    }

    QTextCursor cursor(doc);
    cursor.beginEditBlock();
    if (target.isValid()) {
        cursor.setPosition(target.position());
        cursor.setPosition(target.position() + target.length() - 1, QTextCursor::KeepAnchor);
        cursor.insertText(text);
    } else if (lastB.isValid()) {
        // a new line after the last B statement
        cursor.setPosition(lastB.position() + lastB.length() - 1);
        cursor.insertText(QStringLiteral("\n") + text);
    } else {
        cursor.movePosition(QTextCursor::End);
        cursor.insertText(doc->lastBlock().text().isEmpty() ? text : QStringLiteral("\n") + text);
    }
    cursor.endEditBlock();
    editor->setTextCursor(cursor);
}

}  // namespace studio
