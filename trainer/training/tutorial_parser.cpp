// Parsing a tutorial file (docs/training.md "The file"): statements one per line,
// tokenized by the model language's lexer, read as written into a TutorialSpec.

#include "trainer/training/tutorial.h"

#include "solver/parse/lexer.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <set>
#include <string_view>

namespace trainer {

std::string LocalText::in(const std::string& language) const
{
    if (auto it = byLanguage.find(language); it != byLanguage.end()) return it->second;
    if (auto it = byLanguage.find("en"); it != byLanguage.end()) return it->second;
    return byLanguage.empty() ? std::string() : byLanguage.begin()->second;
}

namespace {

using solver::Diagnostics;
using solver::SourcePos;
using solver::Text;
using solver::plainText;
using solver::trText;
using solver::parse::Token;

constexpr double kDeg = std::numbers::pi / 180.0;

/// Reads one statement's tokens left to right, reporting what is missing or wrong at
/// the token (or after the last one).
class Line {
public:
    Line(const std::vector<Token>& t, Diagnostics& d, int lineNo) : m_t(t), m_d(d), m_line(lineNo) {}

    bool atEnd() const { return m_i >= m_t.size(); }
    const Token& peek() const { return m_t[m_i]; }
    bool failed() const { return m_failed; }
    SourcePos pos() const { return atEnd() ? endPos() : m_t[m_i].pos; }
    SourcePos endPos() const
    {
        if (m_t.empty()) return {m_line, 1};
        const Token& last = m_t.back();
        return {m_line, last.pos.column + static_cast<int>(last.text.size()) + (last.isString() ? 2 : 0)};
    }

    void error(const std::string& code, SourcePos p, Text message, Text hint = {})
    {
        if (m_failed) return;  // one error per statement: the rest follows from it
        m_d.error(code, p, std::move(message), std::move(hint));
        m_failed = true;
    }

    /// The next token if it is the keyword `kw` (consumed).
    bool accept(std::string_view kw)
    {
        if (!atEnd() && peek().isWord() && peek().is(kw)) {
            ++m_i;
            return true;
        }
        return false;
    }
    /// `where` says where the keyword goes (the statement's syntax); may be empty.
    bool expect(std::string_view kw, const Text& where = {})
    {
        if (accept(kw)) return true;
        error("expected-keyword", pos(), trText("Tutorials", "expected %1 %2").with(std::string(kw)).with(where),
              trText("Tutorials", "write %1 followed by its value").with(std::string(kw)));
        return false;
    }
    double number(const Text& what)
    {
        if (m_failed) return 0.0;
        if (atEnd() || !peek().isNumber()) {
            Text message = atEnd() ? trText("Tutorials", "expected %1, found the end of the line").with(what)
                                   : trText("Tutorials", "expected %1, found '%2'").with(what).with(peek().text);
            Text hint = trText("Tutorials", "write a number such as 0.5");
            const std::string problem = atEnd() ? std::string() : solver::parse::numberProblem(peek().text);
            if (problem == "not-finite") {
                message = trText("Tutorials", "%1: '%2' is not a finite number").with(what).with(peek().text);
            } else if (problem == "out-of-range") {
                message = trText("Tutorials", "%1: '%2' is too large for a number").with(what).with(peek().text);
                hint = trText("Tutorials", "write a number within ±1e308; check the units");
            } else if (problem == "decimal-comma") {
                std::string dotted = peek().text;
                for (char& c : dotted) {
                    if (c == ',') c = '.';
                }
                hint = trText("Tutorials", "decimals take a point, not a comma: %1").with(dotted);
            }
            error("expected-number", pos(), std::move(message), std::move(hint));
            return 0.0;
        }
        return m_t[m_i++].number;
    }
    double angle(const Text& what)
    {
        const double v = number(what);
        return accept("DEG") ? v * kDeg : v;
    }
    int integer(const Text& what)
    {
        const SourcePos p = pos();
        const double v = number(what);
        if (m_failed) return 0;
        if (v != std::floor(v) || std::abs(v) > 1e9) {
            error("expected-integer", p, trText("Tutorials", "%1 must be a whole number").with(what),
                  trText("Tutorials", "write it without decimals"));
            return 0;
        }
        return static_cast<int>(v);
    }
    Eigen::Vector3d vec3(const Text& what)
    {
        Eigen::Vector3d v;
        for (int k = 0; k < 3; ++k) v[k] = number(trText("Tutorials", "%1 (three numbers: x y z)").with(what));
        return v;
    }
    Eigen::Vector3d unit(const Text& what)
    {
        const SourcePos p = pos();
        Eigen::Vector3d v = vec3(what);
        if (m_failed) return Eigen::Vector3d::UnitX();
        if (v.norm() < 1e-9) {
            error("zero-direction", p, trText("Tutorials", "%1 is the zero vector").with(what),
                  trText("Tutorials", "give a direction, e.g. 0 0 1"));
            return Eigen::Vector3d::UnitX();
        }
        return v.normalized();
    }
    std::string string(const Text& what)
    {
        if (m_failed) return {};
        if (atEnd() || !peek().isString()) {
            error("expected-string", pos(), trText("Tutorials", "expected %1 in double quotes").with(what),
                  trText("Tutorials", "write it as \"…\""));
            return {};
        }
        return m_t[m_i++].text;
    }
    /// An id: a word or a string.
    std::string name(const Text& what)
    {
        if (m_failed) return {};
        if (atEnd() || peek().isNumber()) return string(what);
        return m_t[m_i++].text;
    }
    /// ES "…" EN "…" (each language once; at least one).
    void texts(LocalText& out)
    {
        out.pos = pos();
        while (!atEnd() && !m_failed && peek().isWord()) {
            const Token& k = peek();
            std::string lang;
            for (const std::string& l : kTutorialLanguages) {
                if (k.is(solver::parse::upper(l))) lang = l;
            }
            if (lang.empty()) return;
            ++m_i;
            if (out.byLanguage.count(lang)) {
                error("duplicate-language", k.pos,
                      trText("Tutorials", "the text is given twice in %1").with(solver::parse::upper(lang)),
                      trText("Tutorials", "keep one"));
                return;
            }
            out.byLanguage[lang] = string(trText("Tutorials", "the %1 text").with(solver::parse::upper(lang)));
        }
        if (out.byLanguage.empty()) {
            error("expected-text", pos(), trText("Tutorials", "expected the text in each language: ES \"…\" EN \"…\""),
                  trText("Tutorials", "every text a person reads is written in Spanish and English"));
        }
    }
    void end()
    {
        if (!atEnd() && !m_failed) {
            error("unexpected-token", pos(), trText("Tutorials", "unexpected '%1' here").with(peek().text),
                  trText("Tutorials", "remove it, or check the statement's keywords in docs/training.md"));
        }
    }

private:
    const std::vector<Token>& m_t;
    Diagnostics& m_d;
    int m_line;
    std::size_t m_i = 1;  // after the statement keyword
    bool m_failed = false;
};

/// `what` names the value (a phrase, or a keyword as plainText).
void positive(Line& l, double v, SourcePos p, const Text& what, bool orZero = false)
{
    if (l.failed()) return;
    if (!std::isfinite(v) || v < 0 || (!orZero && v == 0)) {
        l.error("out-of-range", p,
                orZero ? trText("Tutorials", "%1 must not be negative").with(what)
                       : trText("Tutorials", "%1 must be greater than 0").with(what),
                trText("Tutorials", "give a positive value"));
    }
}

}  // namespace

TutorialSpec parseTutorial(const std::string& text, const std::string& file, Diagnostics& diags)
{
    TutorialSpec t;
    t.file = file;
    std::set<std::string> seen;  // statements allowed once
    enum class Last { None, Goal, Worker, Grip, Part } last = Last::None;
    bool sawTutorial = false;
    bool sawWeights = false;
    SourcePos weightsPos;

    std::size_t start = 0;
    int lineNo = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string_view lineText(text.data() + start, end - start);
        if (!lineText.empty() && lineText.back() == '\r') lineText.remove_suffix(1);
        ++lineNo;
        start = end + 1;
        const std::vector<Token> tokens = solver::parse::tokenizeLine(lineText, lineNo, diags);
        if (tokens.empty()) {
            if (end == text.size()) break;
            continue;
        }
        const Token& kw = tokens.front();
        Line l(tokens, diags, lineNo);
        const std::string key = kw.isWord() ? solver::parse::upper(kw.text) : std::string();
        auto once = [&] {
            if (!seen.insert(key).second) {
                l.error("duplicate-statement", kw.pos, trText("Tutorials", "%1 is given twice").with(key),
                        trText("Tutorials", "keep one %1 statement").with(key));
            }
        };
        auto needGoal = [&]() -> Goal* {
            if (last != Last::Goal || t.goals.empty()) {
                l.error("misplaced-statement", kw.pos,
                        trText("Tutorials", "%1 belongs to a GOAL and must follow it").with(key),
                        trText("Tutorials", "put it on the lines after its GOAL statement"));
                return nullptr;
            }
            return &t.goals.back();
        };

        if (key == "TUTORIAL") {
            once();
            sawTutorial = true;
            t.id = l.name(trText("Tutorials", "the tutorial's id, e.g. T0"));
            if (l.accept("LEVEL")) t.level = l.integer(trText("Tutorials", "the level"));
            last = Last::None;
        } else if (key == "TITLE") {
            once();
            l.texts(t.title);
        } else if (key == "INTRO") {
            t.intro.emplace_back();
            l.texts(t.intro.back());
        } else if (key == "MODEL" || key == "SCENE" || key == "PROFILE") {
            once();
            const SourcePos p = l.pos();
            const std::string v = l.string(key == "PROFILE" ? trText("Tutorials", "the station profile's name or file")
                                                            : trText("Tutorials", "the file's path"));
            if (key == "MODEL") t.modelPath = v, t.modelPos = p;
            if (key == "SCENE") t.scenePath = v, t.scenePos = p;
            if (key == "PROFILE") t.profile = v, t.profilePos = p;
        } else if (key == "DEMO") {
            once();
            t.demoPos = l.pos();
            t.demoPath = l.string(trText("Tutorials", "the demonstration's input log"));
            if (l.accept("CAMERA")) t.cameraPath = l.string(trText("Tutorials", "the demonstration's camera path"));
        } else if (key == "DRIVES") {
            once();
            t.drivesPos = l.pos();
            while (!l.atEnd() && !l.failed()) t.drives.push_back(l.integer(trText("Tutorials", "a drive's joint id")));
            if (t.drives.empty()) {
                l.error("expected-number", l.pos(), trText("Tutorials", "DRIVES lists no drive"),
                        trText("Tutorials", "write the joint ids of the drives the operator may use"));
            }
        } else if (key == "SET") {
            TutorialSpec::Set s;
            s.pos = l.pos();
            s.jointId = l.integer(trText("Tutorials", "the joint id"));
            s.value = l.angle(trText("Tutorials", "the joint's initial value"));
            t.initial.push_back(s);
        } else if (key == "TIME") {
            once();
            const SourcePos p = l.pos();
            l.expect("LIMIT", trText("Tutorials", "(TIME LIMIT seconds PAR seconds)"));
            t.scoring.timeLimit = l.number(trText("Tutorials", "the time limit [s]"));
            positive(l, t.scoring.timeLimit, p, trText("Tutorials", "the time limit"));
            const SourcePos pp = l.pos();
            if (l.expect("PAR", trText("Tutorials", "(the time that earns every time point)"))) {
                t.scoring.parTime = l.number(trText("Tutorials", "the par time [s]"));
                positive(l, t.scoring.parTime, pp, trText("Tutorials", "the par time"));
                if (!l.failed() && t.scoring.parTime > t.scoring.timeLimit) {
                    l.error("out-of-range", pp, trText("Tutorials", "the par time is longer than the time limit"),
                            trText("Tutorials", "make PAR at most LIMIT"));
                }
            }
        } else if (key == "PASS") {
            once();
            const SourcePos p = l.pos();
            t.scoring.pass = l.number(trText("Tutorials", "the pass mark (0–100)"));
            if (!l.failed() && (t.scoring.pass < 0 || t.scoring.pass > 100)) {
                l.error("out-of-range", p, trText("Tutorials", "the pass mark must be between 0 and 100"),
                        trText("Tutorials", "e.g. PASS 60"));
            }
        } else if (key == "WEIGHTS") {
            once();
            sawWeights = true;
            weightsPos = kw.pos;
            l.expect("TIME", trText("Tutorials", "(WEIGHTS TIME a PATH b SMOOTH c SAFETY d)"));
            t.scoring.wTime = l.number(trText("Tutorials", "the time weight"));
            l.expect("PATH");
            t.scoring.wPath = l.number(trText("Tutorials", "the path weight"));
            l.expect("SMOOTH");
            t.scoring.wSmooth = l.number(trText("Tutorials", "the smoothness weight"));
            l.expect("SAFETY");
            t.scoring.wSafety = l.number(trText("Tutorials", "the safety weight"));
            for (double w : {t.scoring.wTime, t.scoring.wPath, t.scoring.wSmooth, t.scoring.wSafety}) {
                if (!l.failed() && w < 0) {
                    l.error("out-of-range", kw.pos, trText("Tutorials", "a weight is negative"),
                            trText("Tutorials", "weights are points, 0 or more"));
                }
            }
        } else if (key == "JERK") {
            once();
            const SourcePos p = l.pos();
            t.scoring.jerkReference = l.number(trText("Tutorials", "the reference RMS jerk [m/s³]"));
            positive(l, t.scoring.jerkReference, p, trText("Tutorials", "the reference jerk"));
        } else if (key == "TRACK") {
            once();
            l.expect("BODY", trText("Tutorials", "(TRACK BODY id POINT x y z)"));
            t.trackBodyId = l.integer(trText("Tutorials", "the body id"));
            l.expect("POINT");
            t.trackPoint = l.vec3(trText("Tutorials", "the point on the body"));
            t.track = true;
        } else if (key == "GRIP") {
            once();
            Grip& g = t.grip;
            g.present = true;
            g.pos = kw.pos;
            l.expect("LOAD", trText("Tutorials", "(GRIP LOAD body AT x y z TOOL body AT x y z TOL d ANGTOL a)"));
            g.loadBodyId = l.integer(trText("Tutorials", "the load's body id"));
            l.expect("AT", trText("Tutorials", "(the grip point on the load, in its frame)"));
            g.loadPoint = l.vec3(trText("Tutorials", "the grip point on the load"));
            l.expect("TOOL", trText("Tutorials", "(the body that grips)"));
            g.toolBodyId = l.integer(trText("Tutorials", "the tool's body id"));
            l.expect("AT", trText("Tutorials", "(the grip point on the tool, in its frame)"));
            g.toolPoint = l.vec3(trText("Tutorials", "the grip point on the tool"));
            SourcePos p = l.pos();
            l.expect("TOL", trText("Tutorials", "(how close the two grip points must be [m])"));
            g.tolerance = l.number(trText("Tutorials", "the grip's position tolerance [m]"));
            positive(l, g.tolerance, p, trText("Tutorials", "the grip's tolerance"));
            p = l.pos();
            l.expect("ANGTOL", trText("Tutorials", "(how far the load's attitude may be from the tool's)"));
            g.angleTolerance = l.angle(trText("Tutorials", "the grip's angle tolerance"));
            positive(l, g.angleTolerance, p, trText("Tutorials", "the grip's angle tolerance"));
            if (l.accept("ROT")) {
                const Eigen::Vector3d axis = l.unit(trText("Tutorials", "the load's rotation axis in the tool frame"));
                const double a = l.angle(trText("Tutorials", "the rotation angle"));
                g.relative = Eigen::AngleAxisd(a, axis).toRotationMatrix();
            }
            last = Last::Grip;
        } else if (key == "CLAW") {
            if (last != Last::Grip) {
                l.error("misplaced-statement", kw.pos, trText("Tutorials", "CLAW belongs to GRIP and must follow it"),
                        trText("Tutorials", "put the CLAW lines after the GRIP statement"));
            } else {
                JointTarget c, o;
                c.pos = o.pos = l.pos();
                c.jointId = o.jointId = l.integer(trText("Tutorials", "the claw's joint id"));
                l.expect("CLOSE", trText("Tutorials", "(CLAW joint CLOSE value OPEN value)"));
                c.value = l.number(trText("Tutorials", "the value past which the claw is closed"));
                l.expect("OPEN");
                o.value = l.number(trText("Tutorials", "the value past which the claw is open"));
                if (!l.failed() && c.value == o.value) {
                    l.error("out-of-range", c.pos, trText("Tutorials", "CLOSE and OPEN are the same value"),
                            trText("Tutorials", "OPEN is nearer the claw's open end than CLOSE"));
                }
                t.grip.close.push_back(c);
                t.grip.open.push_back(o);
            }
        } else if (key == "FINGERS") {
            if (last != Last::Grip) {
                l.error("misplaced-statement", kw.pos, trText("Tutorials", "FINGERS belongs to GRIP and must follow it"),
                        trText("Tutorials", "put it after the GRIP statement"));
            }
            while (!l.atEnd() && !l.failed()) t.grip.fingerBodyIds.push_back(l.integer(trText("Tutorials", "a body id")));
        } else if (key == "GOAL") {
            Goal g;
            g.pos = kw.pos;
            g.id = l.name(trText("Tutorials", "the goal's id"));
            for (const Goal& o : t.goals) {
                if (!l.failed() && o.id == g.id) {
                    l.error("duplicate-id", g.pos, trText("Tutorials", "goal '%1' is defined twice").with(g.id),
                            trText("Tutorials", "give every goal its own id"));
                }
            }
            if (l.accept("REACH")) {
                g.kind = Goal::Kind::Reach;
                l.expect("BODY", trText("Tutorials", "(GOAL id REACH BODY b POINT x y z AT x y z TOL d)"));
                g.bodyId = l.integer(trText("Tutorials", "the body id"));
                l.expect("POINT", trText("Tutorials", "(the point on the body, in its frame)"));
                g.point = l.vec3(trText("Tutorials", "the point on the body"));
                l.expect("AT", trText("Tutorials", "(the target in the world)"));
                g.target = l.vec3(trText("Tutorials", "the target"));
                const SourcePos p = l.pos();
                l.expect("TOL", trText("Tutorials", "(how near [m])"));
                g.tolerance = l.number(trText("Tutorials", "the tolerance [m]"));
                positive(l, g.tolerance, p, trText("Tutorials", "the tolerance"));
            } else if (l.accept("JOINT")) {
                g.kind = Goal::Kind::Joint;
            } else if (l.accept("GRASP")) {
                g.kind = Goal::Kind::Grasp;
            } else if (l.accept("PLACE")) {
                g.kind = Goal::Kind::Place;
                l.expect("AT", trText("Tutorials", "(GOAL id PLACE AT x y z TOL d: the load's centre of mass)"));
                g.target = l.vec3(trText("Tutorials", "the load's target position"));
                const SourcePos p = l.pos();
                l.expect("TOL", trText("Tutorials", "(how near [m])"));
                g.tolerance = l.number(trText("Tutorials", "the tolerance [m]"));
                positive(l, g.tolerance, p, trText("Tutorials", "the tolerance"));
                if (l.accept("FIX")) g.fix = true;
                if (l.accept("SEAT")) {
                    const SourcePos sp = l.pos();
                    g.seat = l.number(trText("Tutorials", "the seat zone [m]"));
                    positive(l, g.seat, sp, plainText("SEAT"));
                }
            } else {
                l.error("unknown-goal", l.pos(), trText("Tutorials", "expected the kind of goal: REACH, JOINT, GRASP or PLACE"),
                        trText("Tutorials", "e.g. GOAL g1 REACH BODY 6 POINT 0 0 0 AT 1 2 0.5 TOL 0.1"));
            }
            t.goals.push_back(g);
            last = Last::Goal;
        } else if (key == "ALIGN") {
            if (Goal* g = needGoal()) {
                Alignment a;
                a.pos = l.pos();
                a.local = l.unit(trText("Tutorials", "the direction on the body"));
                l.expect("WITH", trText("Tutorials", "(ALIGN x y z WITH x y z ANGTOL a)"));
                a.world = l.unit(trText("Tutorials", "the direction in the world"));
                const SourcePos p = l.pos();
                l.expect("ANGTOL", trText("Tutorials", "(the angle tolerance)"));
                a.tolerance = l.angle(trText("Tutorials", "the angle tolerance"));
                positive(l, a.tolerance, p, trText("Tutorials", "the angle tolerance"));
                if (g->kind != Goal::Kind::Reach && g->kind != Goal::Kind::Place) {
                    l.error("misplaced-statement", a.pos, trText("Tutorials", "ALIGN applies to REACH and PLACE goals"),
                            trText("Tutorials", "remove it"));
                }
                g->align.push_back(a);
            }
        } else if (key == "JOINT") {
            if (Goal* g = needGoal()) {
                JointTarget j;
                j.pos = l.pos();
                j.jointId = l.integer(trText("Tutorials", "the joint id"));
                l.expect("AT", trText("Tutorials", "(JOINT id AT value TOL d)"));
                j.value = l.angle(trText("Tutorials", "the joint's target"));
                const SourcePos p = l.pos();
                l.expect("TOL");
                j.tolerance = l.angle(trText("Tutorials", "the tolerance"));
                positive(l, j.tolerance, p, trText("Tutorials", "the tolerance"));
                if (g->kind != Goal::Kind::Joint) {
                    l.error("misplaced-statement", j.pos, trText("Tutorials", "JOINT lines belong to a JOINT goal"),
                            trText("Tutorials", "write GOAL id JOINT, then the JOINT lines"));
                }
                g->joints.push_back(j);
            }
        } else if (key == "DWELL") {
            if (Goal* g = needGoal()) {
                const SourcePos p = l.pos();
                g->dwell = l.number(trText("Tutorials", "the dwell time [s]"));
                positive(l, g->dwell, p, trText("Tutorials", "the dwell time"), true);
            }
        } else if (key == "NAME") {
            if (last == Last::Goal && !t.goals.empty()) {
                l.texts(t.goals.back().name);
            } else if (last == Last::Worker && !t.workers.empty()) {
                l.texts(t.workers.back().name);
            } else if (last == Last::Part && !t.parts.empty()) {
                l.texts(t.parts.back().name);
            } else {
                l.error("misplaced-statement", kw.pos,
                        trText("Tutorials", "NAME belongs to a GOAL, a WORKER or a PART and must follow it"),
                        trText("Tutorials", "put it on the line after its GOAL, WORKER or PART"));
            }
        } else if (key == "HINT") {
            Hint h;
            if (l.accept("GOAL")) h.goal = l.name(trText("Tutorials", "the goal's id"));
            if (l.accept("AFTER")) {
                const SourcePos p = l.pos();
                h.after = l.number(trText("Tutorials", "the time on the goal before the hint shows [s]"));
                positive(l, h.after, p, plainText("AFTER"), true);
            }
            l.texts(h.text);
            t.hints.push_back(h);
        } else if (key == "WORKER") {
            Worker w;
            w.pos = kw.pos;
            l.expect("G", trText("Tutorials", "(WORKER G id id … ZONE d PENALTY p: the scene's graphics of the person)"));
            while (!l.atEnd() && !l.failed() && l.peek().isNumber())
                w.graphicIds.push_back(l.integer(trText("Tutorials", "a graphic id")));
            if (!l.failed() && w.graphicIds.empty()) {
                l.error("expected-number", l.pos(), trText("Tutorials", "WORKER lists no graphic"),
                        trText("Tutorials", "give the scene's G ids of the person"));
            }
            if (l.accept("ZONE")) {
                const SourcePos p = l.pos();
                w.zone = l.number(trText("Tutorials", "the safety zone [m]"));
                positive(l, w.zone, p, trText("Tutorials", "the safety zone"));
            }
            if (l.accept("PENALTY")) w.penalty = l.number(trText("Tutorials", "the penalty [points]"));
            t.workers.push_back(w);
            last = Last::Worker;
        } else if (key == "PART") {
            Part part;
            part.pos = kw.pos;
            if (l.accept("MODEL")) part.scene = false;
            else l.accept("SCENE");
            l.expect("G", trText("Tutorials", "(PART [SCENE|MODEL] G id id …, then a NAME line)"));
            while (!l.atEnd() && !l.failed() && l.peek().isNumber())
                part.graphicIds.push_back(l.integer(trText("Tutorials", "a graphic id")));
            if (!l.failed() && part.graphicIds.empty()) {
                l.error("expected-number", l.pos(), trText("Tutorials", "PART lists no graphic"),
                        trText("Tutorials", "give the G ids of the part"));
            }
            t.parts.push_back(part);
            last = Last::Part;
        } else if (key == "AVOID") {
            once();
            l.expect("SCENE", trText("Tutorials", "(AVOID SCENE PENALTY p NEAR d HARD v)"));
            t.scoring.avoidScene = true;
            if (l.accept("PENALTY")) t.scoring.hitPenalty = l.number(trText("Tutorials", "the penalty per hit [points]"));
            if (l.accept("NEAR")) {
                const SourcePos p = l.pos();
                t.scoring.nearDistance = l.number(trText("Tutorials", "the near-miss distance [m]"));
                positive(l, t.scoring.nearDistance, p, plainText("NEAR"), true);
            }
            if (l.accept("HARD")) {
                const SourcePos p = l.pos();
                t.scoring.hardSpeed = l.number(trText("Tutorials", "the speed of a hard hit [m/s]"));
                positive(l, t.scoring.hardSpeed, p, plainText("HARD"));
            }
        } else if (key == "OVERLOAD") {
            once();
            l.expect("PENALTY", trText("Tutorials", "(OVERLOAD PENALTY p)"));
            t.scoring.overloadPenalty = l.number(trText("Tutorials", "the penalty per overload [points]"));
        } else if (key == "LIMITS") {
            once();
            l.expect("PENALTY", trText("Tutorials", "(LIMITS PENALTY p SPEED f)"));
            t.scoring.limitPenalty = l.number(trText("Tutorials", "the penalty per limit bang [points]"));
            if (l.accept("SPEED")) {
                const SourcePos p = l.pos();
                t.scoring.limitSpeedFraction = l.number(trText("Tutorials", "the fraction of the drive's speed"));
                positive(l, t.scoring.limitSpeedFraction, p, plainText("SPEED"), true);
            }
        } else if (key == "DROP") {
            once();
            l.expect("PENALTY", trText("Tutorials", "(DROP PENALTY p)"));
            t.scoring.dropPenalty = l.number(trText("Tutorials", "the penalty for releasing the load out of place [points]"));
        } else {
            l.error("unknown-statement", kw.pos, trText("Tutorials", "unknown statement '%1'").with(kw.text),
                    trText("Tutorials", "a tutorial's statements are TUTORIAL, TITLE, INTRO, MODEL, SCENE, PROFILE, "
                                        "DEMO, DRIVES, SET, TIME, PASS, WEIGHTS, JERK, TRACK, GRIP, CLAW, FINGERS, "
                                        "GOAL (with ALIGN, JOINT, DWELL, NAME), HINT, WORKER, PART, AVOID, OVERLOAD, "
                                        "LIMITS, DROP"));
        }
        l.end();
        if (key != "GOAL" && key != "ALIGN" && key != "JOINT" && key != "DWELL" && key != "NAME" && key != "WORKER" && key != "PART" &&
            key != "GRIP" && key != "CLAW" && key != "FINGERS") {
            last = Last::None;
        }
        if (end == text.size()) break;
    }
    if (!sawTutorial) {
        diags.error("missing-statement", {1, 1}, trText("Tutorials", "the file has no TUTORIAL statement"),
                    trText("Tutorials", "start the file with TUTORIAL <id>, e.g. TUTORIAL T0"));
    }
    if (t.modelPath.empty() && sawTutorial) {
        diags.error("missing-statement", {1, 1}, trText("Tutorials", "the tutorial names no MODEL"),
                    trText("Tutorials", "add MODEL \"path/to/model.pad\""));
    }
    if (t.goals.empty() && sawTutorial) {
        diags.error("missing-statement", {1, 1}, trText("Tutorials", "the tutorial has no GOAL"),
                    trText("Tutorials", "add at least one GOAL"));
    }
    if (sawWeights) {
        const Scoring& s = t.scoring;
        const double sum = s.wTime + s.wPath + s.wSmooth + s.wSafety;
        if (std::abs(sum - 100.0) > 1e-9) {
            diags.error("weights-sum", weightsPos,
                        trText("Tutorials", "the weights add up to %1, not 100").with(std::to_string(sum).substr(0, 6)),
                        trText("Tutorials", "the score is out of 100: make TIME + PATH + SMOOTH + SAFETY = 100"));
        }
    }
    return t;
}

}  // namespace trainer
