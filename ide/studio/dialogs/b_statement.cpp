#include "ide/studio/dialogs/b_statement.h"

#include "solver/parse/writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace studio::bstatement {

QString number(double v)
{
    if (v == 0) return QStringLiteral("0");
    char buf[64];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 6);
    if (ec != std::errc()) return QString::number(v, 'g', 6);
    return QString::fromLatin1(buf, static_cast<int>(p - buf));
}

QString format(int id, const solver::MassProperties& p)
{
    const Eigen::Matrix3d& i = p.inertia;
    const double iScale = i.diagonal().cwiseAbs().maxCoeff();
    const auto moment = [&](double v) { return number(std::abs(v) <= 1e-9 * iScale ? 0.0 : v); };
    const double cScale = std::max(1.0, p.com.cwiseAbs().maxCoeff());
    const auto length = [&](double v) { return number(std::abs(v) <= 1e-12 * cScale ? 0.0 : v); };
    return QStringLiteral("B %1 %2 %3 %4 %5 %6 %7 %8 CG %9 %10 %11")
        .arg(QString::number(id), number(p.mass), moment(i(0, 0)), moment(i(1, 1)), moment(i(2, 2)), moment(i(0, 1)),
             moment(i(1, 2)), moment(i(0, 2)), length(p.com.x()))
        .arg(length(p.com.y()), length(p.com.z()));
}

QString nameToken(const std::string& name)
{
    if (name.empty()) return {};
    QString s = QString::fromStdString(name);
    s.replace(QLatin1Char('\\'), QStringLiteral("\\\\"));
    s.replace(QLatin1Char('"'), QStringLiteral("\\\""));
    return QStringLiteral("NAME \"%1\"").arg(s);
}

QString fromSpec(const solver::BodySpec& b)
{
    const auto n = [](double v) { return QString::fromStdString(solver::parse::formatNumber(v)); };
    QString s = QStringLiteral("B %1").arg(b.id);
    if (b.hasMass) {
        s += QStringLiteral(" %1 %2 %3 %4").arg(n(b.mass), n(b.inertia.x()), n(b.inertia.y()), n(b.inertia.z()));
        if (b.hasProducts) s += QStringLiteral(" %1 %2 %3").arg(n(b.products.x()), n(b.products.y()), n(b.products.z()));
    }
    if (b.hasCg) s += QStringLiteral(" CG %1 %2 %3").arg(n(b.cg.x()), n(b.cg.y()), n(b.cg.z()));
    if (!b.name.empty()) s += QLatin1Char(' ') + nameToken(b.name);
    return s;
}

QString replaceInLine(const QString& line, const QString& statement)
{
    const auto blank = [](QChar c) { return c == QLatin1Char(' ') || c == QLatin1Char('\t'); };
    qsizetype k = 0;
    const qsizetype n = line.size();
    while (k < n && blank(line[k])) ++k;
    const qsizetype start = k;
    if (k + 1 >= n || (line[k] != QLatin1Char('B') && line[k] != QLatin1Char('b')) || !blank(line[k + 1])) return {};
    // the statement's tokens up to a comment (// or #) or the end of the line
    qsizetype stmtEnd = k;
    QString name;  // NAME's string token as written
    bool afterName = false;
    while (k < n) {
        if (blank(line[k])) {
            ++k;
            continue;
        }
        if (line[k] == QLatin1Char('#') || line.mid(k, 2) == QLatin1String("//")) break;
        qsizetype t = k;
        if (line[k] == QLatin1Char('"')) {
            // a string, with \" and \\ inside
            t = k + 1;
            while (t < n && line[t] != QLatin1Char('"')) t += line[t] == QLatin1Char('\\') ? 2 : 1;
            if (t >= n) return {};
            ++t;
        } else {
            while (t < n && !blank(line[t]) && line[t] != QLatin1Char('"')) ++t;
        }
        const QString token = line.mid(k, t - k);
        if (afterName) {
            if (!token.startsWith(QLatin1Char('"'))) return {};
            name = token;
            afterName = false;
        } else if (token.compare(QLatin1String("NAME"), Qt::CaseInsensitive) == 0) {
            afterName = true;
        }
        stmtEnd = t;
        k = t;
    }
    if (afterName) return {};
    const QString replacement = statement + (name.isEmpty() ? QString() : QStringLiteral(" NAME ") + name);
    // keep a trailing comment where it was when there is room, else two spaces before it
    QString gap = line.mid(stmtEnd, k - stmtEnd);
    if (k < n && gap.size() >= 2 && !gap.contains(QLatin1Char('\t'))) {
        const qsizetype commentColumn = k;
        const qsizetype newEnd = start + replacement.size();
        gap = QString(commentColumn >= newEnd + 2 ? commentColumn - newEnd : 2, QLatin1Char(' '));
    }
    return line.left(start) + replacement + gap + line.mid(k);
}

}  // namespace studio::bstatement
