#include "trainer/centre/messages.h"

#include <initializer_list>

namespace trainer::centre {

namespace {

struct Field {
    const char* name;
    const std::string* value;
    std::size_t max;
    bool plain = false;  ///< no control characters (names, operator codes)
};

std::string check(std::initializer_list<Field> fields)
{
    for (const Field& f : fields) {
        if (f.value->size() > f.max) {
            return std::string(f.name) + ": " + std::to_string(f.value->size()) + " bytes, at most " + std::to_string(f.max);
        }
        if (f.plain) {
            for (const char c : *f.value) {
                const auto u = static_cast<unsigned char>(c);
                if (u < 0x20 || u == 0x7f) return std::string(f.name) + ": a control character";
            }
        }
    }
    return {};
}

std::string count(const char* name, std::size_t n, std::size_t max)
{
    return n > max ? std::string(name) + ": " + std::to_string(n) + " entries, at most " + std::to_string(max) : std::string();
}

}  // namespace

std::string clip(const std::string& s, std::size_t max)
{
    if (s.size() <= max) return s;
    std::size_t n = max;
    while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80) --n;  // not inside a character
    return s.substr(0, n);
}

std::string limitProblem(const Announce& a)
{
    using namespace limits;
    if (std::string why = count("tutorials", a.tutorials.size(), kTutorials); !why.empty()) return why;
    for (const std::string& t : a.tutorials) {
        if (std::string why = check({{"tutorials", &t, kWord, true}}); !why.empty()) return why;
    }
    return check({{"node", &a.node, kName, true},
                  {"role", &a.role, kWord, true},
                  {"host", &a.host, kField, true},
                  {"model", &a.model, kField, true},
                  {"modelHash", &a.modelHash, kField, true},
                  {"language", &a.language, kWord, true},
                  {"mac", &a.mac, kMac, true}});
}

std::string limitProblem(const State& s)
{
    using namespace limits;
    if (std::string why = count("q", s.q.size(), kJoints); !why.empty()) return why;
    if (std::string why = count("commands", s.commands.size(), kJoints); !why.empty()) return why;
    return check({{"station", &s.station, kName, true},
                  {"tutorial", &s.tutorial, kWord, true},
                  {"status", &s.status, kWord, true},
                  {"operatorCode", &s.operatorCode, kOperatorCode, true},
                  {"faults", &s.faults, kText},
                  {"endReason", &s.endReason, kField},
                  {"mac", &s.mac, kMac, true}});
}

std::string limitProblem(const Event& e)
{
    using namespace limits;
    return check({{"station", &e.station, kName, true},
                  {"tutorial", &e.tutorial, kWord, true},
                  {"kind", &e.kind, kWord, true},
                  {"text", &e.text, kText},
                  {"detail", &e.detail, kField},
                  {"mac", &e.mac, kMac, true}});
}

std::string limitProblem(const Command& c)
{
    using namespace limits;
    // start's second argument is the operator's code
    const std::size_t arg2Max = c.kind == "start" ? kOperatorCode : kField;
    return check({{"target", &c.target, kName, true},
                  {"sender", &c.sender, kName, true},
                  {"kind", &c.kind, kWord, true},
                  {"arg", &c.arg, kField, true},
                  {c.kind == "start" ? "operatorCode" : "arg2", &c.arg2, arg2Max, true},
                  {"mac", &c.mac, kMac, true}});
}

std::string limitProblem(const Reply& r)
{
    using namespace limits;
    return check({{"station", &r.station, kName, true},
                  {"sender", &r.sender, kName, true},
                  {"message", &r.message, kText},
                  {"mac", &r.mac, kMac, true}});
}

}  // namespace trainer::centre
