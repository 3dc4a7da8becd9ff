#include "solver/parse/parser.h"

#include "solver/parse/keywords.h"
#include "solver/parse/lexer.h"

#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <type_traits>

namespace solver::parse {

namespace {

using namespace std::string_view_literals;

constexpr double kDegToRad = std::numbers::pi / 180.0;

/// The statements a line may start with, for "did you mean" suggestions.
constexpr const auto& kStatementKeywords = keywords::kStatements;

std::string fmt(double v)
{
    char buf[64];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, p) : std::string("?");
}

std::size_t editDistance(std::string_view a, std::string_view b)
{
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

/// The closest of `candidates` to `word`, when it is close enough to be a typo.
template <typename Range>
std::string closest(std::string_view word, const Range& candidates)
{
    std::string best;
    std::size_t bestDist = 3;
    std::string w = upper(word);
    if (w.size() > 12) return {};
    for (std::string_view c : candidates) {
        std::size_t d = editDistance(w, c);
        if (d < bestDist && d < std::max<std::size_t>(2, c.size())) {
            bestDist = d;
            best = std::string(c);
        }
    }
    return best;
}

/// "write <syntax>": the hint of a statement written wrong.
Text write(std::string syntax)
{
    return trText("Diagnostics", "write %1").with(std::move(syntax));
}

/// A Text built only when a diagnostic needs it, so that a statement written right
/// costs no phrases: it refers to a callable that makes the Text (a lambda) or to a
/// Text. Like a function reference it does not own what it refers to: pass it down
/// to the call it is made for, never keep it (a LazyText made from a temporary lambda
/// and stored in a variable dangles).
class LazyText {
public:
    template <class F>
        requires(!std::is_same_v<F, LazyText> && !std::is_same_v<F, Text> && std::is_invocable_r_v<Text, const F&>)
    LazyText(const F& make)  // NOLINT(google-explicit-constructor): a lambda is passed as a LazyText
        : m_obj(&make), m_make([](const void* o) -> Text { return (*static_cast<const F*>(o))(); })
    {
    }
    LazyText(const Text& text)  // NOLINT(google-explicit-constructor)
        : m_obj(&text), m_make([](const void* o) -> Text { return *static_cast<const Text*>(o); })
    {
    }
    Text operator()() const { return m_make(m_obj); }

private:
    const void* m_obj;
    Text (*m_make)(const void*);
};

Text didYouMean(std::string guess)
{
    return trText("Diagnostics", "did you mean '%1'?").with(std::move(guess));
}

/// How an option's arguments look.
enum class Arg {
    Int,     ///< an id
    Num,     ///< one number
    NumDeg,  ///< one number, optionally followed by DEG
    Vec3,    ///< three numbers
    Num4,    ///< four numbers (ROT ax ay az deg)
    Num2,    ///< two numbers (DEAD Va Vb)
    Word,    ///< one word (COMP PRE)
    Mag,     ///< a magnitude spec
    Flag,    ///< no argument
    Str,     ///< a string
};

struct OptionDef {
    /// An option whose argument is shown as written (a syntax such as "x y z").
    OptionDef(const char* k, Arg a, const char* syntax) : key(k), arg(a), what(plainText(syntax)) {}
    /// An option whose argument is named by a translatable phrase.
    OptionDef(const char* k, Arg a, Text w) : key(k), arg(a), what(std::move(w)) {}

    std::string_view key;  ///< a string literal
    Arg arg;
    Text what;  ///< what the argument is, for messages and syntax hints ("the lower limit")
};

struct OptionValue {
    double num = 0;
    bool deg = false;
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    Eigen::Vector4d v4 = Eigen::Vector4d::Zero();
    int id = 0;
    std::string str;
    MagnitudeSpec mag;
    SourcePos pos;       ///< the option keyword
    SourcePos valuePos;  ///< its first argument
    bool ok = true;
};

using Options = std::map<std::string, OptionValue, std::less<>>;

class Parser {
public:
    Parser(ModelSpec& spec, Diagnostics& diags) : m_spec(spec), m_d(diags) {}

    void parseLine(std::string_view line, int lineNo)
    {
        tokenizeLine(line, lineNo, m_d, m_toks);
        m_i = 0;
        m_keys.clear();
        m_lineNo = lineNo;
        m_line = line;
        if (m_toks.empty()) return;
        const Token& first = m_toks[0];
        if (!first.isWord()) {
            m_d.error("expected-keyword", first.pos,
                      first.isString()
                          ? trText("Diagnostics", "a statement cannot start with a string")
                          : trText("Diagnostics", "a statement starts with a keyword, not with the number %1").with(first.text),
                      trText("Diagnostics", "start the line with GRAVITY, B, C, D, F or G, or join it to the line above"));
            closeJoint();
            return;
        }
        std::string kw = upper(first.text);
        m_i = 1;
        if (kw == "B1"sv || kw == "B2"sv) { parseJointSide(kw == "B1"sv ? 1 : 2); return; }
        if (kw == "CL1"sv || kw == "CL2"sv) { parseCl(); return; }
        closeJoint();
        if (kw == "GRAVITY"sv) parseGravity();
        else if (kw == "RESTITUTION"sv) parseRestitution();
        else if (kw == "FLUID"sv) parseFluid();
        else if (kw == "PUMP"sv) parsePump();
        else if (kw == "CONTACT"sv) parseContact();
        else if (kw == "B"sv) parseBody();
        else if (kw == "C"sv) parseJoint();
        else if (kw == "D"sv) parseDrive();
        else if (kw == "F"sv) parseForce();
        else if (kw == "G"sv) parseGraphic();
        else {
            std::string guess = closest(kw, kStatementKeywords);
            m_d.error("unknown-keyword", first.pos, trText("Diagnostics", "unknown keyword '%1'").with(first.text),
                      guess.empty() ? trText("Diagnostics", "statements are GRAVITY, RESTITUTION, FLUID, PUMP, B, C "
                                                            "(with B1, B2, CL1), D, F and G; comments start with // or #")
                                    : didYouMean(guess));
        }
    }

    void closeJoint() { m_joint = -1; }

private:
    ModelSpec& m_spec;
    Diagnostics& m_d;
    std::vector<Token> m_toks;
    std::size_t m_i = 0;
    int m_lineNo = 0;
    std::string_view m_line;  // the line being parsed (its end's column is worked out when asked for)
    int m_joint = -1;  // index of the joint whose B1/B2/CL lines may follow
    /// The option keywords of the statement being parsed (string literals): a word in a
    /// number's place that is none of them (nor a typo of one) is a malformed number,
    /// not an option.
    std::vector<std::string_view> m_keys;
    SourcePos m_tableJointPos;  // the joint id of the last `TABLE Q joint`

    // ---- token access ---------------------------------------------------------
    bool atEnd() const { return m_i >= m_toks.size(); }
    const Token& peek() const { return m_toks[m_i]; }
    SourcePos here() const { return atEnd() ? endPos() : peek().pos; }
    /// Just after the line's last character.
    SourcePos endPos() const { return {m_lineNo, columnOf(m_line, m_line.size()) + 1}; }

    /// A token in a number's place: a number, or a word that is a malformed number.
    static bool numberLike(const Token& t)
    {
        if (t.isNumber()) return true;
        if (!t.isWord() || t.text.empty()) return false;
        char c = t.text[0];
        if ((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+') return true;
        return !numberProblem(t.text).empty();
    }

    void setKeys(const std::vector<OptionDef>& defs)
    {
        m_keys.clear();
        for (const OptionDef& d : defs) m_keys.emplace_back(d.key);
    }
    void setKeys(std::initializer_list<const char*> keys) { m_keys.assign(keys.begin(), keys.end()); }

    /// A word in a number's place that is not one of the statement's options (nor,
    /// for words of three or more letters, a typo of one): a number written wrong
    /// (`P1 0 x 0`), reported as such and consumed, so that one mistake gives one
    /// diagnostic instead of "only 1 given" plus "'x' is not an option".
    bool strayWord(const Token& t) const
    {
        if (!t.isWord() || numberLike(t) || isKey(t)) return false;
        return t.text.size() < 3 || closest(t.text, m_keys).empty();
    }

    /// True when `t` is one of the statement's option keywords.
    bool isKey(const Token& t) const
    {
        if (!t.isWord()) return false;
        const std::string u = upper(t.text);
        for (std::string_view k : m_keys) {
            if (u == k) return true;
        }
        return false;
    }

    /// A token in a number's place that is reported as a malformed number.
    bool badNumberLike(const Token& t) const { return numberLike(t) || strayWord(t); }

    /// Reports why the number-like word `t` is not a number.
    /// `context` says where (trText("Diagnostics", "body %1")).
    void badNumber(const Token& t, LazyText context, bool& ok)
    {
        ok = false;
        std::string why = numberProblem(t.text);
        if (why == "decimal-comma") {
            std::string dotted = t.text;
            dotted[dotted.find(',')] = '.';
            m_d.error("decimal-comma", t.pos, trText("Diagnostics", "%1: '%2' is not a number").with(context()).with(t.text),
                      trText("Diagnostics", "use '.' as the decimal separator: %1").with(dotted));
        } else if (why == "not-finite") {
            m_d.error("not-finite", t.pos, trText("Diagnostics", "%1: '%2' is not a finite number").with(context()).with(t.text),
                      trText("Diagnostics", "write a finite value; NaN and infinity are not allowed"));
        } else if (why == "out-of-range") {
            m_d.error("number-out-of-range", t.pos, trText("Diagnostics", "%1: %2 is out of range").with(context()).with(t.text),
                      trText("Diagnostics", "a number must lie within ±1.7e308"));
        } else {
            m_d.error("not-a-number", t.pos, trText("Diagnostics", "%1: '%2' is not a number").with(context()).with(t.text),
                      trText("Diagnostics", "numbers look like 12, -0.5, .2 or 1e-3"));
        }
    }

    /// Reads one number. On a missing number reports "<context>: <what> is missing"
    /// with the hint `fix` (write(syntax)), and consumes nothing.
    std::optional<double> number(LazyText context, LazyText what, bool& ok, LazyText fix)
    {
        if (!atEnd() && peek().isNumber()) return m_toks[m_i++].number;
        if (!atEnd() && badNumberLike(peek())) {
            badNumber(m_toks[m_i++], context, ok);
            return std::nullopt;
        }
        ok = false;
        if (atEnd()) {
            m_d.error("missing-number", here(), trText("Diagnostics", "%1: %2 is missing").with(context()).with(what()),
                      fix());
        } else {
            m_d.error("missing-number", here(),
                      trText("Diagnostics", "%1: expected %2, found '%3'").with(context()).with(what()).with(peek().text),
                      fix());
        }
        return std::nullopt;
    }

    /// Reads `n` numbers into `out`; reports one diagnostic for the first problem.
    template <int N>
    bool numbers(Eigen::Matrix<double, N, 1>& out, LazyText context, std::string_view key, LazyText fix, bool& ok)
    {
        for (int k = 0; k < N; ++k) {
            if (!atEnd() && peek().isNumber()) {
                out[k] = m_toks[m_i++].number;
                continue;
            }
            if (!atEnd() && badNumberLike(peek())) {
                badNumber(m_toks[m_i++], context, ok);
                continue;
            }
            ok = false;
            Text message = k > 0     ? trText("Diagnostics", "%1: %2 needs %3 numbers, only %4 given")
                           : atEnd() ? trText("Diagnostics", "%1: %2 needs %3 numbers, the line ends")
                                     : trText("Diagnostics", "%1: %2 needs %3 numbers, found '%4'");
            message.arg(context()).arg(std::string(key)).arg(N);
            if (k > 0) message.arg(k);
            else if (!atEnd()) message.arg(peek().text);
            m_d.error("missing-number", here(), std::move(message), fix());
            return false;
        }
        return true;
    }

    /// Reads an id (0 … INT_MAX).
    std::optional<int> readId(LazyText context, LazyText what, bool& ok, LazyText fix)
    {
        if (atEnd() || !numberLike(peek())) {
            ok = false;
            m_d.error("missing-id", here(),
                      atEnd() ? trText("Diagnostics", "%1: %2 is missing").with(context()).with(what())
                              : trText("Diagnostics", "%1: %2 is missing, found '%3'")
                                    .with(context())
                                    .with(what())
                                    .with(peek().text),
                      fix());
            if (!atEnd() && strayWord(peek())) ++m_i;  // it stood in the id's place
            return std::nullopt;
        }
        const Token& t = m_toks[m_i++];
        std::string_view s = t.text;
        if (!s.empty() && s[0] == '+') s.remove_prefix(1);
        bool digitsOnly = !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
        if (!digitsOnly) {
            ok = false;
            if (t.isNumber() && t.number < 0) {
                m_d.error("bad-id", t.pos,
                          trText("Diagnostics", "%1: %2 cannot be negative (%3)").with(context()).with(what()).with(t.text),
                          trText("Diagnostics", "ids are whole numbers 0, 1, 2, …"));
            } else if (t.isNumber()) {
                m_d.error("bad-id", t.pos,
                          trText("Diagnostics", "%1: %2 must be a whole number, not %3").with(context()).with(what()).with(t.text),
                          trText("Diagnostics", "ids are whole numbers 0, 1, 2, …"));
            } else {
                badNumber(t, context, ok);
            }
            return std::nullopt;
        }
        long long v = 0;
        auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (ec != std::errc() || v > INT_MAX) {
            ok = false;
            m_d.error("bad-id", t.pos, trText("Diagnostics", "%1: %2 %3 is too large").with(context()).with(what()).with(t.text),
                      trText("Diagnostics", "ids go from 0 to %1").with(std::to_string(INT_MAX)));
            return std::nullopt;
        }
        return static_cast<int>(v);
    }

    /// Parses a magnitude: number | SIN amp freq phase [offset] | TABLE T t v … | TABLE Q j q v …
    bool magnitude(MagnitudeSpec& mag, LazyText context, bool& ok)
    {
        const Text fix = trText("Diagnostics", "write MAG value, MAG SIN amp freq phase [offset], "
                                               "MAG TABLE T t1 v1 t2 v2 … or MAG TABLE Q joint q1 v1 …");
        mag.pos = here();
        if (!atEnd() && numberLike(peek())) {
            mag.kind = MagnitudeSpec::Kind::Constant;
            auto v = number(context, trText("Diagnostics", "the magnitude"), ok, fix);
            mag.value = v.value_or(0);
            return v.has_value();
        }
        if (!atEnd() && peek().is("SIN")) {
            ++m_i;
            mag.kind = MagnitudeSpec::Kind::Sine;
            Eigen::Vector3d v;
            if (!numbers<3>(v, context, "SIN", [] { return write("SIN amplitude frequency[Hz] phase[rad] [offset]"); },
                            ok)) {
                return false;
            }
            mag.amplitude = v[0];
            mag.frequency = v[1];
            mag.phase = v[2];
            if (!atEnd() && numberLike(peek())) {
                auto off = number(context, trText("Diagnostics", "the offset"), ok, fix);
                mag.offset = off.value_or(0);
                mag.hasOffset = true;
            }
            return true;
        }
        if (!atEnd() && peek().is("TABLE")) {
            SourcePos tablePos = peek().pos;
            ++m_i;
            if (!atEnd() && peek().is("T")) {
                ++m_i;
                mag.kind = MagnitudeSpec::Kind::TableTime;
            } else if (!atEnd() && peek().is("Q")) {
                ++m_i;
                mag.kind = MagnitudeSpec::Kind::TableJoint;
                m_tableJointPos = here();
                auto j = readId(context, trText("Diagnostics", "the joint of TABLE Q"), ok,
                                [] { return write("TABLE Q joint q1 v1 q2 v2 …"); });
                if (!j) return false;
                mag.joint = *j;
            } else {
                ok = false;
                m_d.error("bad-table", here(),
                          trText("Diagnostics", "%1: TABLE must say T (by time) or Q (by a joint's coordinate)")
                              .with(context()),
                          trText("Diagnostics", "write TABLE T t1 v1 t2 v2 … or TABLE Q joint q1 v1 q2 v2 …"));
                // skip the table, so that its letter and numbers give no second diagnostic
                if (!atEnd() && peek().isWord() && !isKey(peek())) ++m_i;
                while (!atEnd() && numberLike(peek())) ++m_i;
                return false;
            }
            std::vector<double> vals;
            std::vector<SourcePos> where;
            while (!atEnd() && numberLike(peek())) {
                where.push_back(peek().pos);
                auto v = number(context, trText("Diagnostics", "a table value"), ok, fix);
                vals.push_back(v.value_or(0));
            }
            if (vals.size() < 2 || vals.size() % 2 != 0) {
                ok = false;
                m_d.error("bad-table", vals.empty() ? here() : where.back(),
                          (vals.size() == 1
                               ? trText("Diagnostics", "%1: a TABLE needs pairs of numbers (abscissa value), found %2 number")
                               : trText("Diagnostics", "%1: a TABLE needs pairs of numbers (abscissa value), found %2 numbers"))
                              .with(context())
                              .with(std::to_string(vals.size())),
                          write("TABLE T t1 v1 t2 v2 …"));
                return false;
            }
            for (std::size_t k = 0; k + 1 < vals.size(); k += 2) mag.table.emplace_back(vals[k], vals[k + 1]);
            for (std::size_t k = 1; k < mag.table.size(); ++k) {
                if (!(mag.table[k].first > mag.table[k - 1].first)) {
                    ok = false;
                    m_d.error("table-not-increasing", where[2 * k],
                              trText("Diagnostics", "%1: table abscissae must increase (%2 follows %3)")
                                  .with(context())
                                  .with(fmt(mag.table[k].first))
                                  .with(fmt(mag.table[k - 1].first)),
                              trText("Diagnostics", "sort the pairs by their first number and remove repeats"));
                    break;
                }
            }
            (void)tablePos;
            return true;
        }
        ok = false;
        m_d.error("missing-number", here(),
                  atEnd() ? trText("Diagnostics", "%1: MAG needs a value").with(context())
                          : trText("Diagnostics", "%1: MAG needs a value, found '%2'").with(context()).with(peek().text),
                  fix);
        return false;
    }

    /// Parses keyword options in any order until the line ends.
    Options options(const std::vector<OptionDef>& defs, LazyText context, LazyText statementName, bool& ok)
    {
        Options out;
        setKeys(defs);
        const std::vector<std::string_view>& names = m_keys;  // the option keywords, in the order of defs
        auto listNames = [&] {
            std::string s;
            for (std::size_t k = 0; k < names.size(); ++k) s += (k ? ", " : "") + std::string(names[k]);
            return s;
        };
        while (!atEnd()) {
            const Token& t = peek();
            const OptionDef* def = nullptr;
            if (t.isWord()) {
                std::string key = upper(t.text);
                for (const OptionDef& d : defs) {
                    if (key == d.key) def = &d;
                }
            }
            if (!def) {
                ok = false;
                if (numberLike(t)) {
                    m_d.error("extra-number", t.pos, trText("Diagnostics", "%1: unexpected number %2").with(context()).with(t.text),
                              names.empty() ? trText("Diagnostics", "remove it")
                                            : trText("Diagnostics", "remove it, or put an option before it (%1)")
                                                  .with(listNames()));
                } else {
                    std::string guess = t.isWord() ? closest(t.text, names) : std::string();
                    m_d.error("unknown-option", t.pos,
                              trText("Diagnostics", "%1: '%2' is not an option of %3")
                                  .with(context())
                                  .with(t.text)
                                  .with(statementName()),
                              !guess.empty()  ? didYouMean(guess)
                              : names.empty() ? trText("Diagnostics", "remove it")
                                              : trText("Diagnostics", "options are %1").with(listNames()));
                }
                ++m_i;
                // skip to the next word, so one typo gives one diagnostic
                while (!atEnd() && !peek().isWord()) ++m_i;
                continue;
            }
            OptionValue val;
            val.pos = t.pos;
            ++m_i;
            val.valuePos = here();
            std::string key(def->key);
            bool dup = out.count(key) > 0;
            auto fix = [&] { return trText("Diagnostics", "write %1 %2").with(key).with(def->what); };
            auto what = [&] { return trText("Diagnostics", "%1 after %2").with(def->what).with(key); };
            switch (def->arg) {
            case Arg::Int: {
                auto id = readId(context, what, val.ok, fix);
                val.id = id.value_or(0);
                break;
            }
            case Arg::Num:
            case Arg::NumDeg: {
                auto v = number(context, what, val.ok, fix);
                val.num = v.value_or(0);
                if (def->arg == Arg::NumDeg && !atEnd() && peek().is("DEG")) {
                    val.deg = true;
                    ++m_i;
                }
                break;
            }
            case Arg::Vec3: numbers<3>(val.v, context, key, fix, val.ok); break;
            case Arg::Num4: numbers<4>(val.v4, context, key, fix, val.ok); break;
            case Arg::Num2: {
                Eigen::Matrix<double, 2, 1> two;
                numbers<2>(two, context, key, fix, val.ok);
                val.v.head<2>() = two;
                break;
            }
            case Arg::Word:
                if (!atEnd() && peek().isWord() && !isKey(peek())) {
                    val.str = upper(m_toks[m_i++].text);
                } else {
                    val.ok = false;
                    m_d.error("missing-word", here(), trText("Diagnostics", "%1: %2 needs a word").with(context()).with(key),
                              fix());
                }
                break;
            case Arg::Mag: magnitude(val.mag, context, val.ok); break;
            case Arg::Flag: break;
            case Arg::Str:
                if (!atEnd() && peek().isString()) {
                    val.str = m_toks[m_i++].text;
                } else if (!atEnd() && peek().isWord() && !isKey(peek())) {
                    // a text without quotes (NAME GIRO PLUMA): its words give one diagnostic,
                    // then the options after them are read
                    val.ok = false;
                    const SourcePos at = peek().pos;
                    std::string words = m_toks[m_i++].text;
                    while (!atEnd() && peek().isWord() && !isKey(peek())) words += " " + m_toks[m_i++].text;
                    m_d.error("missing-string", at,
                              trText("Diagnostics", "%1: %2 needs a text in double quotes").with(context()).with(key),
                              write(key + " \"" + words + "\""));
                } else {
                    val.ok = false;
                    m_d.error("missing-string", here(),
                              trText("Diagnostics", "%1: %2 needs a text in double quotes").with(context()).with(key),
                              write(key + " \"text\""));
                }
                break;
            }
            if (!val.ok) ok = false;
            if (dup) {
                ok = false;
                m_d.error("duplicate-option", val.pos, trText("Diagnostics", "%1: %2 is given twice").with(context()).with(key),
                          trText("Diagnostics", "keep one %1").with(key));
                continue;
            }
            out.emplace(key, std::move(val));
        }
        return out;
    }

    void requireOptions(const Options& opts, std::initializer_list<const char*> keys, LazyText context, LazyText fix,
                        SourcePos pos, bool& ok)
    {
        requireOptions(opts, keys.begin(), keys.end(), context, fix, pos, ok);
    }
    void requireOptions(const Options& opts, const std::vector<const char*>& keys, LazyText context, LazyText fix,
                        SourcePos pos, bool& ok)
    {
        requireOptions(opts, keys.data(), keys.data() + keys.size(), context, fix, pos, ok);
    }
    void requireOptions(const Options& opts, const char* const* first, const char* const* last, LazyText context,
                        LazyText fix, SourcePos pos, bool& ok)
    {
        for (const char* const* k = first; k != last; ++k) {
            if (!opts.count(*k)) {
                ok = false;
                m_d.error("missing-option", pos, trText("Diagnostics", "%1: %2 is missing").with(context()).with(*k),
                          fix());
            }
        }
    }

    static void recordPositions(FieldPositions& src, const Options& opts)
    {
        for (const auto& [k, v] : opts) src.at[k] = v.valuePos;
    }

    // ---- statements -----------------------------------------------------------
    void parseGravity()
    {
        SourcePos pos = m_toks[0].pos;
        bool ok = true;
        Eigen::Vector3d g;
        const Text context = plainText("GRAVITY");
        bool read = numbers<3>(g, context, "GRAVITY", trText("Diagnostics", "write GRAVITY gx gy gz (m/s², z is up)"), ok);
        options({}, context, context, ok);
        if (m_spec.hasGravity) {
            m_d.error("duplicate-gravity", pos,
                      trText("Diagnostics", "%1 is given twice (first at line %2)")
                          .with("GRAVITY")
                          .with(std::to_string(m_spec.gravityPos.line)),
                      trText("Diagnostics", "keep one %1 statement").with("GRAVITY"));
            return;
        }
        m_spec.hasGravity = true;
        m_spec.gravityPos = pos;
        if (read && ok) m_spec.gravity = g;
    }

    void parseRestitution()
    {
        const SourcePos pos = m_toks[0].pos;
        bool ok = true;
        const SourcePos valuePos = here();
        const Text context = plainText("RESTITUTION");
        auto e = number(context, trText("Diagnostics", "the coefficient of restitution"), ok,
                        trText("Diagnostics", "write RESTITUTION e (0 inelastic … 1 elastic)"));
        options({}, context, context, ok);
        if (m_spec.hasRestitution) {
            m_d.error("duplicate-restitution", pos,
                      trText("Diagnostics", "%1 is given twice (first at line %2)")
                          .with("RESTITUTION")
                          .with(std::to_string(m_spec.restitutionPos.line)),
                      trText("Diagnostics", "keep one %1 statement").with("RESTITUTION"));
            return;
        }
        m_spec.hasRestitution = true;
        m_spec.restitutionPos = pos;
        if (!e) return;
        if (*e < 0 || *e > 1) {
            m_d.error("bad-restitution", valuePos, trText("Diagnostics", "RESTITUTION %1 is outside 0 … 1").with(fmt(*e)),
                      trText("Diagnostics", "0 stops a joint dead at its limit, 1 bounces it back at the same speed"));
            return;
        }
        m_spec.restitution = *e;
    }

    /// A statement that may be given once, given again at `pos` (first at `first`).
    void givenTwice(const char* code, const char* keyword, SourcePos pos, SourcePos first)
    {
        m_d.error(code, pos,
                  trText("Diagnostics", "%1 is given twice (first at line %2)").with(keyword).with(std::to_string(first.line)),
                  trText("Diagnostics", "keep one %1 statement").with(keyword));
    }

    /// The options of a statement `keyword` that may be given once, into `opts`, their
    /// positions into out.src; false (reported as `code`) when `first` was given before.
    template <class Spec>
    bool onceOptions(const char* code, const char* keyword, const std::optional<Spec>& first,
                     const std::vector<OptionDef>& defs, Spec& out, Options& opts, bool& ok)
    {
        out.src.pos = m_toks[0].pos;
        const Text context = plainText(keyword);
        opts = options(defs, context, context, ok);
        recordPositions(out.src, opts);
        if (!first) return true;
        givenTwice(code, keyword, out.src.pos, first->src.pos);
        return false;
    }

    void parseFluid()
    {
        static const std::vector<OptionDef> defs = {
            {"BULK", Arg::Num, trText("Diagnostics", "the bulk modulus in Pa")},
            {"LAMINAR", Arg::Num, trText("Diagnostics", "the laminar pressure difference in Pa")}};
        FluidSpec f;
        Options opts;
        bool ok = true;
        if (!onceOptions("duplicate-fluid", "FLUID", m_spec.fluid, defs, f, opts, ok)) return;
        const Text context = plainText("FLUID");
        for (const auto& [k, v] : opts) {
            if (v.ok && !(v.num > 0)) {
                ok = false;
                m_d.error("not-positive", v.valuePos,
                          trText("Diagnostics", "%1: %2 must be positive, not %3").with(context).with(k).with(fmt(v.num)),
                          k == "BULK" ? trText("Diagnostics", "the effective bulk modulus of oil in hoses is about 1e9 Pa")
                                      : trText("Diagnostics", "a few bar, e.g. LAMINAR 2e5"));
            }
        }
        if (auto it = opts.find("BULK"); it != opts.end()) f.bulk = it->second.num;
        if (auto it = opts.find("LAMINAR"); it != opts.end()) f.laminar = it->second.num;
        f.src.complete = ok;
        m_spec.fluid = std::move(f);
    }

    void parseContact()
    {
        ContactSpec c;
        bool ok = true;
        Options opts;  // MU and E, each checked on its own below
        static const std::vector<OptionDef> defs = {
            {"MU", Arg::Num, trText("Diagnostics", "the friction coefficient")},
            {"E", Arg::Num, trText("Diagnostics", "the coefficient of restitution")}};
        if (!onceOptions("duplicate-contact", "CONTACT", m_spec.contact, defs, c, opts, ok)) return;
        if (auto it = opts.find("MU"); it != opts.end() && it->second.ok) {
            if (it->second.num < 0) {
                ok = false;
                m_d.error("bad-friction", it->second.valuePos,
                          trText("Diagnostics", "CONTACT MU %1 is negative").with(fmt(it->second.num)),
                          trText("Diagnostics", "MU is the Coulomb friction coefficient, 0 (frictionless) or more: "
                                                "steel on steel about 0.2 … 0.6"));
            } else {
                c.mu = it->second.num;
            }
        }
        if (auto it = opts.find("E"); it != opts.end() && it->second.ok) {
            if (it->second.num < 0 || it->second.num > 1) {
                ok = false;
                m_d.error("bad-contact-restitution", it->second.valuePos,
                          trText("Diagnostics", "CONTACT E %1 is outside 0 … 1").with(fmt(it->second.num)),
                          trText("Diagnostics", "0 stops a solid dead where it hits, 1 bounces it back at the same speed"));
            } else {
                c.e = it->second.num;
            }
        }
        c.src.complete = ok;
        m_spec.contact = std::move(c);
    }

    void parsePump()
    {
        static constexpr const char* syntax = "PUMP id FLOW Qmax PRESSURE p_max [MARGIN dp] [NAME \"text\"]";
        PumpSpec p;
        p.src.pos = m_toks[0].pos;
        bool ok = true;
        auto id = readId(trText("Diagnostics", "pump"), trText("Diagnostics", "the pump id"), ok,
                         [] { return write(syntax); });
        if (!id) return;
        p.id = *id;
        auto ctx = [&] { return trText("Diagnostics", "pump %1").with(std::to_string(p.id)); };
        static const std::vector<OptionDef> defs = {
            {"FLOW", Arg::Num, trText("Diagnostics", "the largest flow in m³/s")},
            {"PRESSURE", Arg::Num, trText("Diagnostics", "the pressure setting in Pa")},
            {"MARGIN", Arg::Num, trText("Diagnostics", "the load-sensing margin in Pa")},
            {"NAME", Arg::Str, "\"text\""}};
        Options opts = options(defs, ctx, [] { return plainText("PUMP"); }, ok);
        recordPositions(p.src, opts);
        requireOptions(opts, {"FLOW", "PRESSURE"}, ctx, [] { return write(syntax); }, p.src.pos, ok);
        for (const auto& [k, v] : opts) {
            if (k == "NAME" || !v.ok || v.num > 0) continue;
            ok = false;
            m_d.error("not-positive", v.valuePos,
                      trText("Diagnostics", "%1: %2 must be positive, not %3").with(ctx()).with(k).with(fmt(v.num)),
                      trText("Diagnostics", "FLOW in m³/s (45 cm³/rev at 1480 rpm is 1.11e-3), PRESSURE and MARGIN in Pa"));
        }
        if (auto it = opts.find("FLOW"); it != opts.end()) p.flow = it->second.num;
        if (auto it = opts.find("PRESSURE"); it != opts.end()) p.pressure = it->second.num;
        if (auto it = opts.find("MARGIN"); it != opts.end()) p.margin = it->second.num;
        if (auto it = opts.find("NAME"); it != opts.end()) p.name = it->second.str;
        if (const PumpSpec* first = m_spec.pump(p.id)) {
            m_d.error("duplicate-pump", p.src.pos,
                      trText("Diagnostics", "pump %1 is defined twice (first at line %2)")
                          .with(std::to_string(p.id))
                          .with(std::to_string(first->src.pos.line)),
                      trText("Diagnostics", "give each pump its own id"));
            return;
        }
        p.src.complete = ok;
        m_spec.pumps.push_back(std::move(p));
    }

    void parseBody()
    {
        static constexpr const char* syntax = "B id [m Ixx Iyy Izz [Ixy Iyz Ixz]] [CG x y z] [NAME \"text\"]";
        BodySpec b;
        b.src.pos = m_toks[0].pos;
        bool ok = true;
        auto id = readId(trText("Diagnostics", "body"), trText("Diagnostics", "the body id"), ok,
                         [] { return write(syntax); });
        if (!id) {
            b.src.complete = false;
            return;  // a body without an id cannot be referred to; nothing to keep
        }
        b.id = *id;
        auto ctx = [&] { return trText("Diagnostics", "body %1").with(std::to_string(b.id)); };
        static const std::vector<OptionDef> defs = {{"CG", Arg::Vec3, "x y z"}, {"NAME", Arg::Str, "\"text\""}};
        setKeys(defs);
        // count the numbers after the id: 0 (massless), 4 or 7
        std::size_t first = m_i, count = 0;
        while (first + count < m_toks.size() && numberLike(m_toks[first + count])) ++count;
        if (count != 4 && count != 7) {
            // a word among the numbers (`B 1 10 abc 1 1`) that makes the count right is
            // a malformed number, not the start of the options
            std::size_t loose = count;
            while (first + loose < m_toks.size() && badNumberLike(m_toks[first + loose])) ++loose;
            if (loose == 4 || loose == 7) count = loose;
        }
        if (count != 0 && count != 4 && count != 7) {
            ok = false;
            SourcePos at = count > 7 ? m_toks[first + 7].pos : m_toks[first + count - 1].pos;
            m_d.error(count > 7 ? "extra-number" : "missing-number", at,
                      trText("Diagnostics", "%1: a body takes 0, 4 or 7 numbers after its id (m Ixx Iyy Izz [Ixy Iyz "
                                            "Ixz]), found %2")
                          .with(ctx())
                          .with(std::to_string(count)),
                      count < 4   ? trText("Diagnostics", "give the mass and the three moments of inertia: %1").with(syntax)
                      : count < 7 ? trText("Diagnostics", "give all three products of inertia Ixy Iyz Ixz, or none")
                                  : trText("Diagnostics", "remove the extra numbers"));
            m_i += count;
        } else if (count > 0) {
            std::array<double, 7> v{};
            for (std::size_t k = 0; k < count; ++k) {
                const Token& t = m_toks[m_i++];
                if (t.isNumber()) v[k] = t.number;
                else badNumber(t, ctx, ok);
            }
            b.hasMass = true;
            b.mass = v[0];
            b.inertia = {v[1], v[2], v[3]};
            if (count == 7) {
                b.hasProducts = true;
                b.products = {v[4], v[5], v[6]};
            }
            b.src.at["m"] = m_toks[first].pos;
            b.src.at["I"] = m_toks[first + 1].pos;
            if (count == 7) b.src.at["Ixy"] = m_toks[first + 4].pos;
        }
        Options opts = options(defs, ctx, trText("Diagnostics", "a body statement (B)"), ok);
        recordPositions(b.src, opts);
        if (auto it = opts.find("CG"); it != opts.end()) {
            b.hasCg = true;
            b.cg = it->second.v;
        }
        if (auto it = opts.find("NAME"); it != opts.end()) b.name = it->second.str;
        b.src.complete = ok;
        m_spec.bodies.push_back(std::move(b));
    }

    void parseJoint()
    {
        static constexpr const char* syntax = "C id [T 0|1|2|3] [LL v] [UL v] [QI v] [VI v] [NAME \"text\"]";
        JointSpec j;
        j.src.pos = m_toks[0].pos;
        bool ok = true;
        auto id = readId(trText("Diagnostics", "joint"), trText("Diagnostics", "the joint id"), ok,
                         [] { return write(syntax); });
        j.id = id.value_or(-1);
        const bool hasId = id.has_value();
        auto ctx = [&] {
            return hasId ? trText("Diagnostics", "joint %1").with(std::to_string(j.id)) : trText("Diagnostics", "joint");
        };
        static const std::vector<OptionDef> defs = {{"T", Arg::Num, trText("Diagnostics", "the joint type (0, 1, 2 or 3)")},
                                                    {"LL", Arg::NumDeg, trText("Diagnostics", "the lower limit")},
                                                    {"UL", Arg::NumDeg, trText("Diagnostics", "the upper limit")},
                                                    {"QI", Arg::NumDeg, trText("Diagnostics", "the initial coordinate")},
                                                    {"VI", Arg::NumDeg, trText("Diagnostics", "the initial rate")},
                                                    {"NAME", Arg::Str, "\"text\""}};
        Options opts = options(defs, ctx, trText("Diagnostics", "a joint statement (C)"), ok);
        recordPositions(j.src, opts);
        if (auto it = opts.find("T"); it != opts.end() && it->second.ok) {
            j.typeWritten = true;
            // read as a number, so that T 3, T -1 and T 1.5 all get the same message
            const double t = it->second.num;
            if (t == 0) j.type = JointType::Revolute;
            else if (t == 1) j.type = JointType::Actuator;
            else if (t == 2) j.type = JointType::Prismatic;
            else if (t == 3) j.type = JointType::Free;
            else {
                ok = false;
                m_d.error("bad-joint-type", it->second.valuePos,
                          trText("Diagnostics", "%1: there is no joint type T %2").with(ctx()).with(fmt(t)),
                          trText("Diagnostics", "use T 0 (revolute, the default), T 1 (pivoted linear actuator), T 2 "
                                                "(prismatic) or T 3 (free body)"));
            }
        }
        auto take = [&](const char* key, std::optional<double>& out) {
            auto it = opts.find(key);
            if (it == opts.end()) return;
            double v = it->second.num;
            if (it->second.deg) {
                if (j.type != JointType::Revolute && j.type != JointType::Free) {
                    ok = false;
                    m_d.error("deg-on-length", it->second.valuePos,
                              trText("Diagnostics", "%1: DEG after %2, but the coordinate of %3 is a length")
                                  .with(ctx())
                                  .with(key)
                                  .with(j.type == JointType::Actuator
                                            ? trText("Diagnostics", "a pivoted linear actuator (T 1)")
                                            : trText("Diagnostics", "a prismatic joint (T 2)")),
                              trText("Diagnostics", "remove DEG; give the value in metres"));
                }
                v *= kDegToRad;
            }
            out = v;
        };
        take("LL", j.ll);
        take("UL", j.ul);
        take("QI", j.qi);
        take("VI", j.vi);
        if (auto it = opts.find("NAME"); it != opts.end()) j.name = it->second.str;
        j.src.complete = ok;
        if (!id) return;
        m_spec.joints.push_back(std::move(j));
        m_joint = static_cast<int>(m_spec.joints.size()) - 1;
    }

    JointSpec* openJoint(const Token& kwTok)
    {
        if (m_joint < 0) {
            m_d.error("orphan-joint-line", kwTok.pos,
                      trText("Diagnostics", "%1 must follow a joint statement (C)").with(upper(kwTok.text)),
                      trText("Diagnostics", "put it right after its joint's C line (blank and comment lines may come "
                                            "between)"));
            return nullptr;
        }
        return &m_spec.joints[static_cast<std::size_t>(m_joint)];
    }

    void parseJointSide(int side)
    {
        const Token& kw = m_toks[0];
        JointSpec* j = openJoint(kw);
        if (!j) return;
        const std::string s = std::to_string(side);
        const std::string other = side == 1 ? "2" : "1";
        auto fix = [&] { return write("B" + s + " body P" + s + " x y z A" + s + " x y z R" + s + " x y z"); };
        auto ctx = [&] { return trText("Diagnostics", "joint %1, B%2").with(std::to_string(j->id)).with(s); };
        JointSide& js = side == 1 ? j->side1 : j->side2;
        if (js.present) {
            m_d.error("duplicate-joint-line", kw.pos,
                      trText("Diagnostics", "joint %1 already has a B%2 line (line %3)")
                          .with(std::to_string(j->id))
                          .with(s)
                          .with(std::to_string(js.src.pos.line)),
                      trText("Diagnostics", "keep one B%1 line per joint").with(s));
            j->src.complete = false;
            return;
        }
        JointSide side_;
        side_.present = true;
        side_.src.pos = kw.pos;
        bool ok = true;
        // P, A, R with this side's digit; the other side's keys are diagnosed
        static const std::vector<OptionDef> defs1 = {
            {"P1", Arg::Vec3, "x y z"}, {"A1", Arg::Vec3, "x y z"}, {"R1", Arg::Vec3, "x y z"}};
        static const std::vector<OptionDef> defs2 = {
            {"P2", Arg::Vec3, "x y z"}, {"A2", Arg::Vec3, "x y z"}, {"R2", Arg::Vec3, "x y z"}};
        const std::vector<OptionDef>& defs = side == 1 ? defs1 : defs2;
        const char* const kp = side == 1 ? "P1" : "P2";
        const char* const ka = side == 1 ? "A1" : "A2";
        const char* const kr = side == 1 ? "R1" : "R2";
        // a wrong-side key (P2 on a B1 line) gets its own message
        for (std::size_t k = m_i; k < m_toks.size(); ++k) {
            if (!m_toks[k].isWord() || m_toks[k].text.size() != 2) continue;  // the keys are two letters
            std::string u = upper(m_toks[k].text);
            if (u == "P" + other || u == "A" + other || u == "R" + other) {
                ok = false;
                m_d.error("wrong-side", m_toks[k].pos,
                          trText("Diagnostics", "%1: %2 belongs on the B%3 line").with(ctx()).with(u).with(other),
                          trText("Diagnostics", "on the B%1 line write %2").with(s).with(u.substr(0, 1) + s));
                m_toks[k].text = u.substr(0, 1) + s;  // read it as meant, to avoid a second message
            }
        }
        setKeys(defs);
        side_.src.at["B"] = here();
        auto body = readId(ctx, trText("Diagnostics", "the body id"), ok, fix);
        side_.body = body.value_or(-1);
        Options opts = options(defs, ctx, [&] { return trText("Diagnostics", "a B%1 line").with(s); }, ok);
        requireOptions(opts, {kp, ka, kr}, ctx, fix, kw.pos, ok);
        for (const auto& [k, v] : opts) side_.src.at[k.substr(0, 1)] = v.valuePos;
        if (auto it = opts.find(kp); it != opts.end()) side_.p = it->second.v;
        if (auto it = opts.find(ka); it != opts.end()) side_.a = it->second.v;
        if (auto it = opts.find(kr); it != opts.end()) side_.r = it->second.v;
        side_.src.complete = ok;
        if (!ok) j->src.complete = false;
        js = std::move(side_);
    }

    void parseCl()
    {
        const Token& kw = m_toks[0];
        JointSpec* j = openJoint(kw);
        if (!j) return;
        m_i = 0;  // CL1 and CL2 are both options of this line
        auto ctx = [&] { return trText("Diagnostics", "joint %1").with(std::to_string(j->id)); };
        bool ok = true;
        static const std::vector<OptionDef> defs = {{"CL1", Arg::Vec3, "x y z"}, {"CL2", Arg::Vec3, "x y z"}};
        Options opts = options(defs, ctx, trText("Diagnostics", "a CL1/CL2 line"), ok);
        for (const auto& [k, v] : opts) {
            bool have = j->src.at.count(k) > 0;
            if (have) {
                ok = false;
                m_d.error("duplicate-joint-line", v.pos, trText("Diagnostics", "%1: %2 is given twice").with(ctx()).with(k),
                          trText("Diagnostics", "keep one %1").with(k));
                continue;
            }
            j->src.at[k] = v.valuePos;
            (k == "CL1" ? j->cl1 : j->cl2) = v.v;
        }
        j->hasCl = j->src.at.count("CL1") || j->src.at.count("CL2");
        if (!ok) j->src.complete = false;
    }

    void parseDrive()
    {
        DriveSpec d;
        d.src.pos = m_toks[0].pos;
        bool ok = true;
        static constexpr const char* syntax = "D joint HYD|MOTOR|PNEU|SERVO|CYL|HMOTOR parameters…";
        auto joint = readId(trText("Diagnostics", "drive"), trText("Diagnostics", "the joint id"), ok,
                            [] { return write(syntax); });
        if (!joint) return;
        d.joint = *joint;
        auto ctx = [&] { return trText("Diagnostics", "drive on joint %1").with(std::to_string(d.joint)); };
        if (atEnd() || !peek().isWord()) {
            m_d.error("missing-drive-kind", here(), trText("Diagnostics", "%1: the drive kind is missing").with(ctx()),
                      trText("Diagnostics", "write HYD, MOTOR, PNEU, SERVO, CYL or HMOTOR after the joint id"));
            return;
        }
        const Token& kindTok = m_toks[m_i++];
        std::string kind = upper(kindTok.text);
        d.src.at["kind"] = kindTok.pos;
        static const Text speed = trText("Diagnostics", "speed"), force = trText("Diagnostics", "force"),
                          diameter = trText("Diagnostics", "diameter"), gain = trText("Diagnostics", "gain");
        static const std::vector<OptionDef> hydraulicDefs = {
            {"VMAX", Arg::Num, speed},    {"VMIN", Arg::Num, speed},    {"FMAX", Arg::Num, force},
            {"FMIN", Arg::Num, force},    {"PUMP", Arg::Num, "cc/rev"}, {"RPM", Arg::Num, "rpm"},
            {"BORE", Arg::Num, diameter}, {"ROD", Arg::Num, diameter},  {"PRESSURE", Arg::Num, "Pa"}};
        static const std::vector<OptionDef> motorDefs = {{"T0", Arg::Num, trText("Diagnostics", "stall torque")},
                                                         {"W0", Arg::Num, trText("Diagnostics", "no-load speed")}};
        static const std::vector<OptionDef> pneumaticDefs = {{"F", Arg::Num, force}};
        static const std::vector<OptionDef> servoDefs = {
            {"KP", Arg::Num, gain}, {"KI", Arg::Num, gain}, {"KD", Arg::Num, gain}, {"FMAX", Arg::Num, force}};
        const std::vector<OptionDef>* defs = nullptr;
        if (kind == "HYD"sv) {
            d.kind = DriveKind::Hydraulic;
            defs = &hydraulicDefs;
        } else if (kind == "MOTOR"sv) {
            d.kind = DriveKind::Motor;
            defs = &motorDefs;
        } else if (kind == "PNEU"sv) {
            d.kind = DriveKind::Pneumatic;
            defs = &pneumaticDefs;
        } else if (kind == "SERVO"sv) {
            d.kind = DriveKind::Servo;
            defs = &servoDefs;
        } else if (kind == "CYL"sv || kind == "HMOTOR"sv) {
            d.kind = kind == "CYL"sv ? DriveKind::Cylinder : DriveKind::HydraulicMotor;
            parseFluidDrive(d, ctx, ok);
            return;
        } else {
            std::string guess =
                closest(kind, std::array<std::string_view, 6>{"HYD", "MOTOR", "PNEU", "SERVO", "CYL", "HMOTOR"});
            m_d.error("unknown-drive-kind", kindTok.pos,
                      trText("Diagnostics", "%1: unknown drive kind '%2'").with(ctx()).with(kindTok.text),
                      guess.empty() ? trText("Diagnostics", "drive kinds are HYD, MOTOR, PNEU, SERVO, CYL and HMOTOR")
                                    : didYouMean(guess));
            return;
        }
        // the hint for what the kind requires
        auto kindFix = [&]() -> Text {
            switch (d.kind) {
            case DriveKind::Hydraulic:
                return trText("Diagnostics", "write D j HYD VMAX v [VMIN v] [FMAX f] [FMIN f], or D j HYD PUMP cc RPM n "
                                             "BORE d ROD d PRESSURE Pa");
            case DriveKind::Motor: return write("D j MOTOR T0 torque W0 speed");
            case DriveKind::Pneumatic: return write("D j PNEU F force");
            case DriveKind::Servo: return write("D j SERVO KP p KI i KD d [FMAX f]");
            case DriveKind::Cylinder:
            case DriveKind::HydraulicMotor: break;  // parseFluidDrive
            }
            return {};
        };
        Options opts = options(*defs, ctx, [&] { return trText("Diagnostics", "a %1 drive").with(kind); }, ok);
        recordPositions(d.src, opts);
        // parameters in the order written
        std::vector<const Options::value_type*> order;
        order.reserve(opts.size());
        for (const auto& kv : opts) order.push_back(&kv);
        std::sort(order.begin(), order.end(), [](const auto* a, const auto* b) {
            return a->second.pos.column < b->second.pos.column;
        });
        d.params.reserve(order.size());
        for (const auto* kv : order) d.params.emplace_back(kv->first, kv->second.num);
        // what each kind requires
        if (d.kind == DriveKind::Hydraulic) {
            bool hasV = opts.count("VMAX") > 0;
            const std::array pumpKeys = {"PUMP", "RPM", "BORE", "ROD", "PRESSURE"};
            int nPump = 0;
            for (const char* k : pumpKeys) nPump += opts.count(k) ? 1 : 0;
            if (hasV && nPump > 0) {
                ok = false;
                m_d.error("hyd-conflict", d.src.where(opts.count("PUMP") ? "PUMP" : "RPM"),
                          trText("Diagnostics", "%1: give either VMAX/FMAX or the hydraulic data PUMP … PRESSURE, not both")
                              .with(ctx()),
                          trText("Diagnostics", "remove one of the two forms"));
            } else if (nPump > 0) {
                requireOptions(opts, {"PUMP", "RPM", "BORE", "ROD", "PRESSURE"}, ctx, kindFix, d.src.pos, ok);
                for (const char* k : {"VMIN", "FMAX", "FMIN"}) {
                    if (opts.count(k)) {
                        ok = false;
                        m_d.error("hyd-conflict", d.src.where(k),
                                  trText("Diagnostics", "%1: %2 follows from the hydraulic data PUMP … PRESSURE")
                                      .with(ctx())
                                      .with(k),
                                  trText("Diagnostics", "remove %1, or give VMAX/VMIN/FMAX/FMIN instead of the pump data")
                                      .with(k));
                    }
                }
                auto bore = opts.find("BORE"), rod = opts.find("ROD");
                if (bore != opts.end() && rod != opts.end() && rod->second.num >= bore->second.num) {
                    ok = false;
                    m_d.error("rod-too-large", rod->second.valuePos,
                              trText("Diagnostics", "%1: the rod (%2 m) is not thinner than the bore (%3 m)")
                                  .with(ctx())
                                  .with(fmt(rod->second.num))
                                  .with(fmt(bore->second.num)),
                              trText("Diagnostics", "ROD and BORE are diameters in metres; the rod must be thinner"));
                }
            } else if (!hasV) {
                ok = false;
                m_d.error("missing-option", d.src.pos,
                          trText("Diagnostics", "%1: a hydraulic drive needs VMAX or the pump data").with(ctx()), kindFix());
            }
        } else if (d.kind == DriveKind::Motor) {
            requireOptions(opts, {"T0", "W0"}, ctx, kindFix, d.src.pos, ok);
        } else if (d.kind == DriveKind::Pneumatic) {
            requireOptions(opts, {"F"}, ctx, kindFix, d.src.pos, ok);
        } else {
            requireOptions(opts, {"KP", "KI", "KD"}, ctx, kindFix, d.src.pos, ok);
        }
        // magnitudes that must be positive (gains and PNEU F may be zero or signed)
        for (const auto& [k, v] : opts) {
            bool mustBePositive = k != "KP" && k != "KI" && k != "KD" && k != "F";
            if (mustBePositive && v.ok && !(v.num > 0)) {
                ok = false;
                m_d.error("not-positive", v.valuePos,
                          trText("Diagnostics", "%1: %2 must be positive, not %3").with(ctx()).with(k).with(fmt(v.num)),
                          trText("Diagnostics", "give its magnitude; the direction comes from the operator's command"));
            } else if (!mustBePositive && v.ok && v.num < 0 && k != "F") {
                ok = false;
                m_d.error("not-positive", v.valuePos,
                          trText("Diagnostics", "%1: %2 cannot be negative (%3)").with(ctx()).with(k).with(fmt(v.num)),
                          trText("Diagnostics", "gains are zero or positive"));
            }
        }
        d.src.complete = ok;
        m_spec.drives.push_back(std::move(d));
    }

    /// `D j CYL PUMP id BORE d ROD d VALVE Qn DP dpn [COMP NONE|PRE|POST] [TAU t] [DEAD Va Vb]
    /// [FRICTION c] [P0 pa pb]` or `D j HMOTOR PUMP id DISP Dm VALVE Qn DP dpn [COMP …] [TAU t]
    /// [VOLUME Va Vb] [FRICTION c] [P0 pa pb]` (the kind already read).
    template <class Ctx>
    void parseFluidDrive(DriveSpec& d, Ctx ctx, bool& ok)
    {
        const bool cyl = d.kind == DriveKind::Cylinder;
        static const Text volume = trText("Diagnostics", "two volumes in m³"),
                          pressures = trText("Diagnostics", "two pressures in Pa");
        static const std::vector<OptionDef> cylDefs = {
            {"PUMP", Arg::Int, trText("Diagnostics", "the pump id")},
            {"BORE", Arg::Num, trText("Diagnostics", "diameter")},
            {"ROD", Arg::Num, trText("Diagnostics", "diameter")},
            {"VALVE", Arg::Num, trText("Diagnostics", "the nominal flow in m³/s")},
            {"DP", Arg::Num, trText("Diagnostics", "the nominal pressure drop in Pa")},
            {"COMP", Arg::Word, "NONE|PRE|POST"},
            {"TAU", Arg::Num, trText("Diagnostics", "the spool time constant in s")},
            {"DEAD", Arg::Num2, volume},
            {"FRICTION", Arg::Num, trText("Diagnostics", "the viscous friction")},
            {"P0", Arg::Num2, pressures},
            // the prescribed-rate drive's keywords, read to say where they belong
            {"VMAX", Arg::Num, "v"}, {"VMIN", Arg::Num, "v"}, {"FMAX", Arg::Num, "f"}, {"FMIN", Arg::Num, "f"},
            {"RPM", Arg::Num, "n"}, {"PRESSURE", Arg::Num, "p"}};
        static const std::vector<OptionDef> motorDefs = {
            {"PUMP", Arg::Int, trText("Diagnostics", "the pump id")},
            {"DISP", Arg::Num, trText("Diagnostics", "the displacement in m³/rad")},
            {"VALVE", Arg::Num, trText("Diagnostics", "the nominal flow in m³/s")},
            {"DP", Arg::Num, trText("Diagnostics", "the nominal pressure drop in Pa")},
            {"COMP", Arg::Word, "NONE|PRE|POST"},
            {"TAU", Arg::Num, trText("Diagnostics", "the spool time constant in s")},
            {"VOLUME", Arg::Num2, volume},
            {"FRICTION", Arg::Num, trText("Diagnostics", "the viscous friction")},
            {"P0", Arg::Num2, pressures},
            {"VMAX", Arg::Num, "v"}, {"VMIN", Arg::Num, "v"}, {"FMAX", Arg::Num, "f"}, {"FMIN", Arg::Num, "f"},
            {"RPM", Arg::Num, "n"}, {"PRESSURE", Arg::Num, "p"}, {"BORE", Arg::Num, "d"}, {"ROD", Arg::Num, "d"}};
        const char* kind = cyl ? "CYL" : "HMOTOR";
        auto fix = [cyl] {
            return cyl ? write("D j CYL PUMP id BORE d ROD d VALVE Qn DP dpn [COMP NONE|PRE|POST] [TAU t] [DEAD Va Vb] "
                               "[FRICTION c] [P0 pa pb]")
                       : write("D j HMOTOR PUMP id DISP Dm VALVE Qn DP dpn [COMP NONE|PRE|POST] [TAU t] [VOLUME Va Vb] "
                               "[FRICTION c] [P0 pa pb]");
        };
        Options opts = options(cyl ? cylDefs : motorDefs, ctx, [&] { return trText("Diagnostics", "a %1 drive").with(kind); },
                               ok);
        recordPositions(d.src, opts);
        for (const char* k : {"VMAX", "VMIN", "FMAX", "FMIN", "RPM", "PRESSURE", "BORE", "ROD"}) {
            if (cyl && (std::string_view(k) == "BORE" || std::string_view(k) == "ROD")) continue;
            auto it = opts.find(k);
            if (it == opts.end()) continue;
            ok = false;
            m_d.error("hyd-keyword-in-fluid-drive", it->second.pos,
                      trText("Diagnostics", "%1: %2 belongs to the prescribed-rate HYD drive, not to %3")
                          .with(ctx())
                          .with(k)
                          .with(kind),
                      cyl ? trText("Diagnostics", "a CYL drive's speed follows from VALVE and BORE, its force from the "
                                                  "PUMP's PRESSURE; remove %1 or write the drive as HYD")
                                .with(k)
                          : trText("Diagnostics", "an HMOTOR drive's speed follows from VALVE and DISP, its torque from "
                                                  "the PUMP's PRESSURE; remove %1 or write the drive as HYD")
                                .with(k));
            opts.erase(it);
        }
        if (cyl) requireOptions(opts, {"PUMP", "BORE", "ROD", "VALVE", "DP"}, ctx, fix, d.src.pos, ok);
        else requireOptions(opts, {"PUMP", "DISP", "VALVE", "DP"}, ctx, fix, d.src.pos, ok);
        std::vector<const Options::value_type*> order;
        for (const auto& kv : opts) order.push_back(&kv);
        std::sort(order.begin(), order.end(), [](const auto* a, const auto* b) {
            return a->second.pos.column < b->second.pos.column;
        });
        for (const auto* kv : order) {
            const std::string& k = kv->first;
            const OptionValue& v = kv->second;
            if (!v.ok) continue;
            if (k == "COMP") {
                if (v.str != "NONE" && v.str != "PRE" && v.str != "POST") {
                    ok = false;
                    m_d.error("bad-compensation", v.valuePos,
                              trText("Diagnostics", "%1: COMP %2 is not a compensation").with(ctx()).with(v.str),
                              trText("Diagnostics", "write COMP NONE (orifice law), PRE (pre-compensated) or POST "
                                                    "(post-compensated, flow sharing)"));
                }
                d.compensation = v.str;
            } else if (k == "PUMP") {
                d.params.emplace_back(k, static_cast<double>(v.id));
            } else if (k == "DEAD" || k == "VOLUME" || k == "P0") {
                const bool pressure = k == "P0";
                for (int e = 0; e < 2; ++e) {
                    const double x = v.v[e];
                    if (pressure ? x >= 0 : x > 0) continue;
                    ok = false;
                    m_d.error(pressure ? "negative-pressure" : "not-positive", v.valuePos,
                              pressure ? trText("Diagnostics", "%1: P0 %2 is below tank pressure (0)").with(ctx()).with(fmt(x))
                                       : trText("Diagnostics", "%1: %2 must be positive, not %3").with(ctx()).with(k).with(fmt(x)),
                              pressure ? trText("Diagnostics", "pressures are gauge pressures in Pa, 0 or more")
                                       : trText("Diagnostics", "volumes in m³, e.g. 5e-4 for half a litre of hose"));
                    break;
                }
                d.pairs.emplace_back(k, std::pair<double, double>(v.v[0], v.v[1]));
            } else {
                if (k == "FRICTION" ? !(v.num >= 0) : !(v.num > 0)) {
                    ok = false;
                    m_d.error("not-positive", v.valuePos,
                              k == "FRICTION"
                                  ? trText("Diagnostics", "%1: %2 cannot be negative (%3)").with(ctx()).with(k).with(fmt(v.num))
                                  : trText("Diagnostics", "%1: %2 must be positive, not %3").with(ctx()).with(k).with(fmt(v.num)),
                              k == "TAU" ? trText("Diagnostics", "the spool's time constant in seconds, e.g. TAU 0.05")
                                         : trText("Diagnostics", "give its magnitude in SI units"));
                }
                d.params.emplace_back(k, v.num);
            }
        }
        auto bore = opts.find("BORE"), rod = opts.find("ROD");
        if (cyl && bore != opts.end() && rod != opts.end() && bore->second.ok && rod->second.ok &&
            rod->second.num >= bore->second.num) {
            ok = false;
            m_d.error("rod-too-large", rod->second.valuePos,
                      trText("Diagnostics", "%1: the rod (%2 m) is not thinner than the bore (%3 m)")
                          .with(ctx())
                          .with(fmt(rod->second.num))
                          .with(fmt(bore->second.num)),
                      trText("Diagnostics", "ROD and BORE are diameters in metres; the rod must be thinner"));
        }
        d.src.complete = ok;
        m_spec.drives.push_back(std::move(d));
    }

    void parseForce()
    {
        ForceSpec f;
        f.src.pos = m_toks[0].pos;
        bool ok = true;
        static constexpr const char* syntax = "F id POINT|TORQUE|JOINT|SPRING|AERO parameters…";
        auto id = readId(trText("Diagnostics", "force"), trText("Diagnostics", "the force id"), ok,
                         [] { return write(syntax); });
        if (!id) return;
        f.id = *id;
        auto ctx = [&] { return trText("Diagnostics", "force %1").with(std::to_string(f.id)); };
        if (atEnd() || !peek().isWord()) {
            m_d.error("missing-force-kind", here(), trText("Diagnostics", "%1: the force kind is missing").with(ctx()),
                      trText("Diagnostics", "write POINT, TORQUE, JOINT, SPRING or AERO after the force id"));
            return;
        }
        const Token& kindTok = m_toks[m_i++];
        std::string kind = upper(kindTok.text);
        f.src.at["kind"] = kindTok.pos;
        static const Text body = trText("Diagnostics", "body"), coefficient = trText("Diagnostics", "coefficient");
        static const std::vector<OptionDef> pointDefs = {{"B", Arg::Int, body},
                                                         {"P", Arg::Vec3, "x y z"},
                                                         {"DIR", Arg::Vec3, "x y z"},
                                                         {"MAG", Arg::Mag, "spec"},
                                                         {"LOCAL", Arg::Flag, ""}};
        static const std::vector<OptionDef> torqueDefs = {
            {"B", Arg::Int, body}, {"DIR", Arg::Vec3, "x y z"}, {"MAG", Arg::Mag, "spec"}, {"LOCAL", Arg::Flag, ""}};
        static const std::vector<OptionDef> jointDefs = {{"MAG", Arg::Mag, "spec"}};
        static const std::vector<OptionDef> springDefs = {{"B1", Arg::Int, body},
                                                          {"P1", Arg::Vec3, "x y z"},
                                                          {"B2", Arg::Int, body},
                                                          {"P2", Arg::Vec3, "x y z"},
                                                          {"K", Arg::Num, trText("Diagnostics", "stiffness")},
                                                          {"L0", Arg::Num, trText("Diagnostics", "length")},
                                                          {"C", Arg::Num, trText("Diagnostics", "damping")}};
        static const std::vector<OptionDef> aeroDefs = {{"B", Arg::Int, body},
                                                        {"P", Arg::Vec3, "x y z"},
                                                        {"AREA", Arg::Num, trText("Diagnostics", "area")},
                                                        {"CD", Arg::Num, coefficient},
                                                        {"CL", Arg::Num, coefficient},
                                                        {"RHO", Arg::Num, trText("Diagnostics", "density")}};
        const std::vector<OptionDef>* defs = nullptr;
        std::vector<const char*> required;
        const char* ksyn = nullptr;
        if (kind == "POINT"sv) {
            f.kind = ForceKind::Point;
            defs = &pointDefs;
            required = {"B", "P", "DIR", "MAG"};
            ksyn = "F id POINT B body P x y z DIR x y z MAG spec [LOCAL]";
        } else if (kind == "TORQUE"sv) {
            f.kind = ForceKind::Torque;
            defs = &torqueDefs;
            required = {"B", "DIR", "MAG"};
            ksyn = "F id TORQUE B body DIR x y z MAG spec [LOCAL]";
        } else if (kind == "JOINT"sv) {
            f.kind = ForceKind::Joint;
            defs = &jointDefs;
            setKeys(*defs);
            f.src.at["JOINT"] = here();
            auto j = readId(ctx, trText("Diagnostics", "the joint id"), ok,
                            [] { return write("F id JOINT joint MAG spec"); });
            f.joint = j.value_or(-1);
            required = {"MAG"};
            ksyn = "F id JOINT joint MAG spec";
        } else if (kind == "SPRING"sv) {
            f.kind = ForceKind::Spring;
            defs = &springDefs;
            required = {"B1", "P1", "B2", "P2", "K", "L0"};
            ksyn = "F id SPRING B1 i P1 x y z B2 k P2 x y z K k L0 l [C c]";
        } else if (kind == "AERO"sv) {
            f.kind = ForceKind::Aero;
            defs = &aeroDefs;
            required = {"B", "P", "AREA", "CD"};
            ksyn = "F id AERO B body P x y z AREA a CD c [CL c] [RHO r]";
        } else {
            std::string guess = closest(kind, std::array<std::string_view, 5>{"POINT", "TORQUE", "JOINT", "SPRING", "AERO"});
            m_d.error("unknown-force-kind", kindTok.pos,
                      trText("Diagnostics", "%1: unknown force kind '%2'").with(ctx()).with(kindTok.text),
                      guess.empty() ? trText("Diagnostics", "force kinds are POINT, TORQUE, JOINT, SPRING and AERO")
                                    : didYouMean(guess));
            return;
        }
        Options opts = options(*defs, ctx, [&] { return trText("Diagnostics", "a %1 force").with(kind); }, ok);
        requireOptions(opts, required, ctx, [&] { return write(ksyn); }, f.src.pos, ok);
        recordPositions(f.src, opts);
        auto get = [&](const char* k) -> const OptionValue* {
            auto it = opts.find(k);
            return it == opts.end() ? nullptr : &it->second;
        };
        if (auto v = get("B")) f.body = v->id;
        if (auto v = get("B1")) f.body = v->id;
        if (auto v = get("B2")) f.body2 = v->id;
        if (auto v = get("P")) f.point = v->v;
        if (auto v = get("P1")) f.point = v->v;
        if (auto v = get("P2")) f.point2 = v->v;
        if (auto v = get("DIR")) f.dir = v->v;
        if (auto v = get("MAG")) {
            f.mag = v->mag;
            if (f.mag.kind == MagnitudeSpec::Kind::TableJoint) f.src.at["Q"] = m_tableJointPos;
        }
        f.local = get("LOCAL") != nullptr;
        if (auto v = get("K")) f.stiffness = v->num;
        if (auto v = get("L0")) f.restLength = v->num;
        if (auto v = get("C")) { f.damping = v->num; f.hasDamping = true; }
        if (auto v = get("AREA")) f.area = v->num;
        if (auto v = get("CD")) f.cd = v->num;
        if (auto v = get("CL")) { f.cl = v->num; f.hasCl = true; }
        if (auto v = get("RHO")) { f.rho = v->num; f.hasRho = true; }
        f.src.complete = ok;
        m_spec.forces.push_back(std::move(f));
    }

    void parseGraphic()
    {
        GraphicSpec g;
        g.src.pos = m_toks[0].pos;
        bool ok = true;
        static constexpr const char* syntax = "G id B body SHAPE dimensions… [POS x y z] [AXIS x y z] [ROT ax ay az deg] "
                                              "[COLOR r g b] [MASS m | RHO density]";
        auto fix = [] { return write(syntax); };
        auto id = readId(trText("Diagnostics", "graphic"), trText("Diagnostics", "the graphic id"), ok, fix);
        if (!id) return;
        g.id = *id;
        auto ctx = [&] { return trText("Diagnostics", "graphic %1").with(std::to_string(g.id)); };
        if (atEnd() || !peek().is("B")) {
            m_d.error("missing-option", here(), trText("Diagnostics", "%1: B body is missing after the id").with(ctx()),
                      fix());
            return;
        }
        ++m_i;
        // the options of a mesh; the other shapes take all but SCALE
        static const std::vector<OptionDef> meshDefs = {{"POS", Arg::Vec3, "x y z"},
                                                        {"AXIS", Arg::Vec3, "x y z"},
                                                        {"ROT", Arg::Num4, "ax ay az deg"},
                                                        {"COLOR", Arg::Vec3, "r g b"},
                                                        {"MASS", Arg::Num, trText("Diagnostics", "mass")},
                                                        {"RHO", Arg::Num, trText("Diagnostics", "density")},
                                                        {"NOCONTACT", Arg::Flag, ""},
                                                        {"SCALE", Arg::Num, trText("Diagnostics", "factor")}};
        static const std::vector<OptionDef> solidDefs(meshDefs.begin(), meshDefs.end() - 1);
        // a word in the body id's place is a malformed id unless it is a shape
        setKeys({"BOX", "CYL", "TUBE", "SPHERE", "CONE", "ELLIPSOID", "PRISM", "MESH"});
        g.src.at["B"] = here();
        auto body = readId(ctx, trText("Diagnostics", "the body id"), ok, fix);
        g.body = body.value_or(-1);
        if (atEnd() || !peek().isWord()) {
            m_d.error("missing-shape", here(), trText("Diagnostics", "%1: the shape is missing").with(ctx()),
                      trText("Diagnostics", "write BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM or MESH and its dimensions"));
            return;
        }
        const Token& shapeTok = m_toks[m_i++];
        std::string shape = upper(shapeTok.text);
        g.src.at["shape"] = shapeTok.pos;
        struct ShapeDef { const char* key; ShapeKind kind; int n; const char* dims; };
        static const std::array<ShapeDef, 8> shapes = {{
            {"BOX", ShapeKind::Box, 3, "X Y Z"},
            {"CYL", ShapeKind::Cylinder, 2, "R L"},
            {"TUBE", ShapeKind::Tube, 3, "RO RI L"},
            {"SPHERE", ShapeKind::Sphere, 1, "R"},
            {"CONE", ShapeKind::Cone, 2, "R L"},
            {"ELLIPSOID", ShapeKind::Ellipsoid, 3, "A B C"},
            {"PRISM", ShapeKind::Prism, -1, "H x1 y1 x2 y2 x3 y3 …"},
            {"MESH", ShapeKind::Mesh, 0, "\"file\" [SCALE s]"},
        }};
        const ShapeDef* sd = nullptr;
        for (const ShapeDef& s : shapes) {
            if (shape == std::string_view(s.key)) sd = &s;
        }
        if (!sd) {
            std::vector<std::string_view> names;
            for (const ShapeDef& s : shapes) names.push_back(s.key);
            std::string guess = closest(shape, names);
            m_d.error("unknown-shape", shapeTok.pos, trText("Diagnostics", "%1: unknown shape '%2'").with(ctx()).with(shapeTok.text),
                      guess.empty() ? trText("Diagnostics", "shapes are BOX, CYL, TUBE, SPHERE, CONE, ELLIPSOID, PRISM and MESH")
                                    : didYouMean(guess));
            return;
        }
        g.shape = sd->kind;
        const std::vector<OptionDef>& defs = sd->kind == ShapeKind::Mesh ? meshDefs : solidDefs;  // SCALE is for meshes only
        setKeys(defs);
        auto dimsFix = [&] { return write(std::string(sd->key) + " " + sd->dims); };
        g.src.at["dims"] = here();
        if (sd->n > 0) {
            for (int k = 0; k < sd->n; ++k) {
                auto v = number(ctx,
                                [&] {
                                    return trText("Diagnostics", "%1 dimension %2 of %3 (%4)")
                                        .with(sd->key)
                                        .with(std::to_string(k + 1))
                                        .with(std::to_string(sd->n))
                                        .with(sd->dims);
                                },
                                ok, dimsFix);
                if (!v && !ok && (atEnd() || !numberLike(peek()))) break;
                g.dims.push_back(v.value_or(0));
            }
        } else if (sd->kind == ShapeKind::Prism) {
            while (!atEnd() && badNumberLike(peek())) {
                auto v = number(ctx, trText("Diagnostics", "a PRISM value"), ok, dimsFix);
                g.dims.push_back(v.value_or(0));
            }
            if (g.dims.size() < 7 || g.dims.size() % 2 == 0) {
                ok = false;
                m_d.error("bad-prism", g.src.where("dims"),
                          trText("Diagnostics", "%1: PRISM needs its height H and at least three x y vertices, found %2 "
                                                "numbers")
                              .with(ctx())
                              .with(std::to_string(g.dims.size())),
                          dimsFix());
            }
        } else {  // MESH
            if (!atEnd() && peek().isString()) {
                g.meshFile = m_toks[m_i++].text;
            } else if (!atEnd() && peek().isWord() && !isKey(peek())) {
                // a file name without quotes: one diagnostic, and the options after it are read
                ok = false;
                const Token& t = m_toks[m_i++];
                m_d.error("missing-string", t.pos, trText("Diagnostics", "%1: the MESH file name must be in double quotes").with(ctx()),
                          write("MESH \"" + t.text + "\""));
            } else {
                ok = false;
                m_d.error("missing-string", here(), trText("Diagnostics", "%1: MESH needs a file name in double quotes").with(ctx()),
                          trText("Diagnostics", "write MESH \"meshes/part.stl\" (relative to the model file)"));
            }
        }
        Options opts = options(defs, ctx, trText("Diagnostics", "a graphic (G)"), ok);
        recordPositions(g.src, opts);
        auto get = [&](const char* k) -> const OptionValue* {
            auto it = opts.find(k);
            return it == opts.end() ? nullptr : &it->second;
        };
        if (auto v = get("POS")) { g.position = v->v; g.hasPosition = true; }
        if (auto v = get("AXIS")) { g.axis = v->v; g.hasAxis = true; }
        if (auto v = get("ROT")) { g.rotAxis = v->v4.head<3>(); g.rotDeg = v->v4[3]; g.hasRot = true; }
        if (auto v = get("COLOR")) { g.color = v->v; g.hasColor = true; }
        if (auto v = get("MASS")) g.mass = v->num;
        if (auto v = get("RHO")) g.rho = v->num;
        if (auto v = get("SCALE")) { g.scale = v->num; g.hasScale = true; }
        if (get("NOCONTACT")) g.noContact = true;
        if (g.mass && g.rho) {
            ok = false;
            m_d.error("mass-and-rho", g.src.where("RHO"), trText("Diagnostics", "%1: give MASS or RHO, not both").with(ctx()),
                      trText("Diagnostics", "MASS is the solid's mass in kg; RHO its density in kg/m³"));
        }
        g.src.complete = ok;
        m_spec.graphics.push_back(std::move(g));
    }
};

}  // namespace

ModelSpec parseModel(std::string_view text, Diagnostics& diags)
{
    ModelSpec spec;
    Parser parser(spec, diags);
    int lineNo = 0;
    std::size_t start = 0;
    // a UTF-8 byte order mark is not part of the text
    if (text.substr(0, 3) == "\xEF\xBB\xBF") start = 3;
    while (start <= text.size()) {
        std::size_t nl = text.find('\n', start);
        std::size_t end = nl == std::string_view::npos ? text.size() : nl;
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        ++lineNo;
        parser.parseLine(line, lineNo);
        if (nl == std::string_view::npos) break;
        start = nl + 1;
    }
    return spec;
}

}  // namespace solver::parse
