// padrob station: a headless training station on the centre's network.
// padrob instructor: list the stations, watch them, command them.
// padrob centre key: make the centre's key.

#include "ide/cli/centre.h"

#include "ide/cli/cli_io.h"
#include "ide/cli/json_writer.h"
#include "ide/i18n/language.h"
#include "ide/paths/paths.h"
#include "trainer/centre/bus.h"
#include "trainer/centre/instructor_node.h"
#include "trainer/centre/pki.h"
#include "trainer/centre/signing.h"
#include "trainer/centre/station_node.h"
#include "trainer/records/records_db.h"
#include "trainer/station/profile.h"
#include "trainer/station/station.h"
#include "trainer/station/station_engine.h"
#include "trainer/training/runner.h"
#include "trainer/training/tutorial.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QThread>
#include <QSysInfo>

#include <map>
#include <mutex>
#include <span>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <thread>
#include <unistd.h>

namespace ide::cli {

namespace {

using i18n::trStd;
namespace centre = trainer::centre;

std::atomic<bool> g_stop{false};
extern "C" void onSignal(int) { g_stop.store(true); }

/// The options every centre command takes: where the network is, and the key.
struct NetOptions {
    centre::BusOptions bus;
    std::string keyFile;
};

std::string netHelp()
{
    return trStd("padrob", "Network options (every node of a centre uses the same):\n"
                           "  --domain N            the centre's DDS domain, 0-232 (default 0)\n"
                           "  --key FILE            the centre's key (make one with 'padrob centre key FILE'):\n"
                           "                        every node signs what it says with it and ignores what is\n"
                           "                        not signed with it; stations refuse commands without it\n"
                           "  --interface NAME      the network interface to use (name or address; repeatable)\n"
                           "  --peer ADDRESS        discover the other computers by unicast at ADDRESS\n"
                           "                        (repeatable; without it, multicast)\n"
                           "  --loopback            this computer only (--interface 127.0.0.1 --peer 127.0.0.1)\n"
                           "  --security DIR        DDS Security: authenticated, access-controlled, encrypted\n"
                           "                        traffic, with the centre's PKI in DIR and this node's\n"
                           "                        identity in DIR/nodes/NAME (see 'padrob centre pki')\n");
}

/// Takes the network options out of `args`. Returns an error message ("" fine).
std::string takeNet(std::vector<std::string>& args, NetOptions& out)
{
    std::vector<std::string> rest;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&](std::string& v) {
            if (i + 1 >= args.size()) return false;
            v = args[++i];
            return true;
        };
        std::string v;
        if (a == "--domain") {
            if (!value(v)) return fill(trStd("padrob", "%1 needs a value"), {a});
            const auto n = toNumber(v);
            if (!n || *n != std::floor(*n) || *n < 0 || *n > 232)
                return fill(trStd("padrob", "--domain must be a whole number from 0 to 232, not '%1'"), {v});
            out.bus.domain = static_cast<int>(*n);
        } else if (a == "--key") {
            if (!value(out.keyFile)) return fill(trStd("padrob", "%1 needs a value"), {a});
        } else if (a == "--interface") {
            if (!value(v)) return fill(trStd("padrob", "%1 needs a value"), {a});
            out.bus.interfaces.append(QString::fromStdString(v));
        } else if (a == "--peer") {
            if (!value(v)) return fill(trStd("padrob", "%1 needs a value"), {a});
            out.bus.peers.append(QString::fromStdString(v));
        } else if (a == "--security") {
            if (!value(v)) return fill(trStd("padrob", "%1 needs a value"), {a});
            out.bus.securityDir = QString::fromStdString(v);
        } else if (a == "--loopback") {
            out.bus.interfaces = {QStringLiteral("127.0.0.1")};
            out.bus.peers = {QStringLiteral("127.0.0.1")};
        } else {
            rest.push_back(a);
        }
    }
    args = std::move(rest);
    return {};
}

std::unique_ptr<centre::Bus> openBus(const NetOptions& net, unsigned reads)
{
    centre::BusOptions o = net.bus;
    o.reads = reads;
    QString error;
    auto bus = centre::Bus::open(o, &error);
    if (!bus) printErr("padrob: " + error.toStdString() + "\n");
    return bus;
}

double nowS()
{
    using clock = std::chrono::steady_clock;
    static const auto t0 = clock::now();
    return std::chrono::duration<double>(clock::now() - t0).count();
}

/// "user@host:port/database" (user, port optional; host may be a socket folder).
bool parseServer(const std::string& spec, trainer::records::PostgresConfig& out, std::string& why)
{
    QString rest = QString::fromStdString(spec);
    const qsizetype at = rest.indexOf('@');
    if (at >= 0) {
        out.user = rest.left(at);
        rest = rest.mid(at + 1);
    }
    const qsizetype slash = rest.lastIndexOf('/');
    if (slash <= 0 || slash == rest.size() - 1) {
        why = fill(trStd("padrob", "--records-server must be USER@HOST:PORT/DATABASE, not '%1'"), {spec});
        return false;
    }
    out.database = rest.mid(slash + 1);
    rest = rest.left(slash);
    const qsizetype colon = rest.lastIndexOf(':');
    if (colon > 0) {
        bool ok = false;
        out.port = rest.mid(colon + 1).toInt(&ok);
        if (!ok || out.port <= 0 || out.port > 65535) {
            why = fill(trStd("padrob", "--records-server must be USER@HOST:PORT/DATABASE, not '%1'"), {spec});
            return false;
        }
        rest = rest.left(colon);
    }
    out.host = rest;
    return true;
}

// padrob station --------------------------------------------------------------------

std::string stationHelp()
{
    return trStd("padrob", "Usage: padrob station TUTORIAL... --name NAME [OPTIONS]\n"
                           "\n"
                           "Runs a training station without a window on the centre's network: the tutorials'\n"
                           "machine is simulated in real time, its state is streamed for display nodes\n"
                           "(padrob-studio --display-of NAME) and the instructor, its events are sent as they\n"
                           "happen, and the instructor's signed commands are obeyed: start, pause, resume,\n"
                           "reset and stop a tutorial, inject and clear faults. Every attempt is recorded.\n"
                           "Runs until interrupted (Ctrl+C or SIGTERM), then says it is leaving.\n"
                           "\n"
                           "  --name NAME           the station's name, unique in the centre\n"
                           "  --profile P           the operator's devices: a station profile of the model (its\n"
                           "                        name, or a .json file; docs/station.md): gamepads, joysticks,\n"
                           "                        the serial valve console\n"
                           "  --demo                the operator's input is each tutorial's demonstration\n"
                           "                        (a showcase, or a test)\n"
                           "                        Without either, the levers rest.\n"
                           "  --records FILE        record the attempts in this SQLite file (the station's journal)\n"
                           "  --records-server USER@HOST:PORT/DATABASE\n"
                           "                        and sync them to the centre's PostgreSQL server; while it is\n"
                           "                        out of reach the journal keeps them (docs/records.md)\n"
                           "  --records-password FILE\n"
                           "                        the server's password, sealed with the centre's key by\n"
                           "                        'padrob centre seal' (never stored in plain text)\n"
                           "  --for SECONDS         stop after this long\n") +
           "\n" + netHelp();
}

}  // namespace

int runStation(const std::vector<std::string>& argsIn)
{
    std::vector<std::string> args = argsIn;
    for (const std::string& a : args) {
        if (a == "--help" || a == "-h") {
            printOut(stationHelp());
            return kExitOk;
        }
    }
    NetOptions net;
    if (std::string e = takeNet(args, net); !e.empty()) return usageError("station", e);
    centre::StationNodeOptions o;
    o.language = i18n::current();
    std::string recordsPath, profileName, serverSpec, passwordFile;
    double forS = -1;
    std::vector<std::string> files;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--name" && i + 1 < args.size()) {
            o.name = args[++i];
        } else if (a == "--demo") {
            o.demoInput = true;
        } else if (a == "--profile" && i + 1 < args.size()) {
            profileName = args[++i];
        } else if (a == "--records" && i + 1 < args.size()) {
            recordsPath = args[++i];
        } else if (a == "--records-server" && i + 1 < args.size()) {
            serverSpec = args[++i];
        } else if (a == "--records-password" && i + 1 < args.size()) {
            passwordFile = args[++i];
        } else if (a == "--for" && i + 1 < args.size()) {
            const auto v = toNumber(args[++i]);
            if (!v || *v <= 0) return usageError("station", fill(trStd("padrob", "--for must be a positive number of seconds, not '%1'"), {args[i]}));
            forS = *v;
        } else if (a.rfind("--", 0) == 0) {
            return usageError("station", fill(trStd("padrob", "unknown option '%1'"), {a}));
        } else {
            files.push_back(a);
        }
    }
    if (o.name.empty()) return usageError("station", trStd("padrob", "--name is required: the station's name in the centre"));
    if (files.empty()) return usageError("station", trStd("padrob", "give at least one tutorial file (.tut)"));
    if (net.keyFile.empty()) {
        return usageError("station", trStd("padrob", "--key FILE is required: the centre's key signs what the station "
                                                     "says (no instructor or display believes it otherwise) and "
                                                     "checks the instructor's commands"));
    }
    {
        QString error;
        const QString keyFile = QString::fromStdString(net.keyFile);
        if (!o.key.load(keyFile, &error) || !o.key.mayServe(o.name, keyFile, &error)) {
            printErr("padrob station: " + error.toStdString() + "\n");
            return kExitUsage;
        }
        net.bus.key = o.key;
    }
    for (const std::string& f : files) {
        solver::Diagnostics diags;
        auto t = trainer::loadTutorial(f, diags);
        if (!t) {
            for (const solver::Diagnostic& d : diags.items()) printDiagnostic(stderr, d);
            return kExitModelErrors;
        }
        o.tutorials.push_back(std::move(t));
    }
    if (!recordsPath.empty()) {
        o.record = true;
        o.records.journalPath = QString::fromStdString(recordsPath);
        o.pendingFolder = QFileInfo(o.records.journalPath).absolutePath() + "/pending-attempts";
        if (!serverSpec.empty()) {
            std::string why;
            if (!parseServer(serverSpec, o.records.server, why)) return usageError("station", why);
            if (!passwordFile.empty()) {
                // sealed with the centre's key (padrob centre seal): never in plain text on disk
                QFile f(QString::fromStdString(passwordFile));
                QString password;
                if (!f.open(QIODevice::ReadOnly) || !o.key.unseal(QString::fromLatin1(f.readAll().trimmed()), password)) {
                    printErr("padrob station: " +
                             fill(trStd("padrob", "cannot open the sealed password in %1: it must be made by 'padrob centre "
                                                  "seal' with this centre's key"),
                                  {passwordFile}) +
                             "\n");
                    return kExitUsage;
                }
                o.records.server.password = password;
            }
        }
    } else if (!serverSpec.empty()) {
        return usageError("station", trStd("padrob", "--records-server needs --records FILE, the station's local journal"));
    }
    // the operator's devices, read in an input thread of their own (trainer::Station)
    std::unique_ptr<trainer::Station> devices;
    auto latest = std::make_shared<std::pair<std::mutex, std::vector<double>>>();
    if (!profileName.empty()) {
        const trainer::Tutorial& t = *o.tutorials.front();
        trainer::StationProfile profile;
        QString error;
        if (!trainer::tutorialProfile(t, QString::fromStdString(profileName), profile, &error)) {
            printErr("padrob station: " + error.toStdString() + "\n");
            return kExitUsage;
        }
        latest->second.assign(std::size_t(t.model->nb), 0.0);
        devices = std::make_unique<trainer::Station>([latest](std::span<const double> u) {
            std::lock_guard lock(latest->first);
            latest->second.assign(u.begin(), u.end());
        });
        const int nb = t.model->nb;
        const QList<trainer::DriveInfo> drives = trainer::drivesOf(*t.model);
        devices->start(true);
        devices->call([&](trainer::StationEngine& e) {
            e.setDrives(nb, drives);
            for (const trainer::ProfileIssue& i : e.setProfile(profile)) printErr("padrob station: " + i.text().toStdString() + "\n");
        });
        o.input = [latest] {
            std::lock_guard lock(latest->first);
            return latest->second;
        };
    }
    net.bus.node = QString::fromStdString(o.name);
    auto bus = openBus(net, centre::TopicCommand);
    if (!bus) return kExitUsage;
    const std::string name = o.name;
    o.notice = [name](const QString& what) {
        printOut(fill(trStd("padrob", "station %1: %2\n"), {name, what.toStdString()}));
        std::fflush(stdout);
    };
    centre::StationNode node(*bus, std::move(o));
    if (!node.ok()) {
        printErr("padrob station: " + node.error().toStdString() + "\n");
        return kExitUsage;
    }
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    std::thread timer;
    if (forS > 0) {
        timer = std::thread([forS] {
            const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(forS);
            while (!g_stop.load() && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(std::chrono::milliseconds(20));
            g_stop.store(true);
        });
    }
    printOut(fill(trStd("padrob", "station %1: on the centre's network (domain %2), ready\n"), {name, std::to_string(net.bus.domain)}));
    std::fflush(stdout);
    node.run(g_stop);
    if (timer.joinable()) timer.join();
    printOut(fill(trStd("padrob", "station %1: left the centre's network\n"), {name}));
    return kExitOk;
}

// padrob instructor ------------------------------------------------------------------

namespace {

std::string instructorHelp()
{
    return trStd("padrob", "Usage: padrob instructor list|watch|send ... [OPTIONS]\n"
                           "\n"
                           "The instructor's station without a window:\n"
                           "  list [--wait S]       the stations on the network after listening S seconds\n"
                           "                        (default 2): name, status, tutorial, time, score, warnings\n"
                           "  watch [--for S]       print the stations' events and comings and goings as they\n"
                           "                        happen (for S seconds; default until interrupted)\n"
                           "  send STATION COMMAND [ARG [ARG2]] [--value V] [--timeout S]\n"
                           "                        send a signed command and wait for the station's answer:\n"
                           "                          start [TUTORIAL [OPERATOR]], pause, resume, reset, stop,\n"
                           "                          inject FAULT [DRIVE|X,Y,Z], clear FAULT [DRIVE]\n"
                           "                        faults: hose-burst DRIVE, stuck-valve DRIVE [--value U],\n"
                           "                          worker-in X,Y,Z [--value WORKER], power-cut\n"
                           "  --name NAME           the instructor's name (default: instructor@HOST)\n"
                           "  --json                JSON output (one object; watch: one per line)\n"
                           "\n"
                           "Exit status: 0 done or accepted, 1 the station refused or did not answer,\n"
                           "2 usage error.\n") +
           "\n" + netHelp();
}

/// A station's presence and status codes, for a person.
std::string presenceText(const std::string& p)
{
    if (p == "up") return trStd("padrob", "on the network");
    if (p == "silent") return trStd("padrob", "silent");
    if (p == "left") return trStd("padrob", "gone (it left)");
    return p;
}

std::string statusText(const std::string& s)
{
    switch (centre::stationStatus(s)) {
    case centre::StationStatus::Idle: return trStd("padrob", "idle");
    case centre::StationStatus::Running: return trStd("padrob", "running");
    case centre::StationStatus::Paused: return trStd("padrob", "paused");
    case centre::StationStatus::Ended: return trStd("padrob", "ended");
    case centre::StationStatus::Unknown: break;
    }
    return s;
}

void printStation(const centre::StationView& v)
{
    const centre::State& s = v.state;
    std::string line = pad(v.announce.node, 14) + " " + pad(presenceText(v.presence), 16) + " " + pad(v.hasState ? statusText(s.status) : "-", 10) +
                       " " + pad(v.hasState ? s.tutorial : "-", 16) + " " + pad(v.hasState ? fixed(s.attemptTime, 1) : "-", 7, true) +
                       " " + pad(v.hasState ? fixed(s.score, 1) : "-", 6, true) + "  " + (v.hasState ? s.faults : "") + "\n";
    printOut(line);
}

std::string stationJson(const centre::StationView& v)
{
    const centre::State& s = v.state;
    JsonWriter w(false);
    w.beginObject();
    w.key("name").str(v.announce.node);
    w.key("presence").str(v.presence);
    w.key("model").str(v.announce.model);
    w.key("host").str(v.announce.host);
    w.key("pid").integer(v.announce.pid);
    w.key("status").str(v.hasState ? s.status : std::string());
    w.key("tutorial").str(s.tutorial);
    w.key("operator").str(s.operatorCode);
    w.key("time").num(s.attemptTime);
    w.key("sim_time").num(s.simTime);
    w.key("score").num(s.score);
    w.key("goal").integer(s.goal);
    w.key("goals").integer(s.goals);
    w.key("warnings").integer(static_cast<long long>(s.warnings));
    w.key("faults").str(s.faults);
    w.key("end").str(s.endReason);
    w.key("joints").integer(static_cast<long long>(s.q.size()));
    w.key("latency_ms").num(v.latencyMs);
    w.endObject();
    return w.text();
}

std::string eventJson(const centre::Event& e)
{
    JsonWriter w(false);
    w.beginObject();
    w.key("station").str(e.station);
    w.key("seq").integer(static_cast<long long>(e.seq));
    w.key("t").num(e.t);
    w.key("tutorial").str(e.tutorial);
    w.key("kind").str(e.kind);
    w.key("text").str(e.text);
    w.key("detail").str(e.detail);
    w.endObject();
    return w.text();
}

std::string presenceJson(const std::string& station, const std::string& presence)
{
    JsonWriter w(false);
    w.beginObject();
    w.key("station").str(station);
    w.key("presence").str(presence);
    w.endObject();
    return w.text();
}

/// What a refusal code means, for a person.
std::string refusalText(const std::string& code)
{
    if (code == "no-key") return trStd("padrob", "the station has no centre key and takes no commands");
    if (code == "bad-signature") return trStd("padrob", "the signature does not match the station's centre key");
    if (code == "stale") return trStd("padrob", "the command is too old or from the future (check the computers' clocks)");
    if (code == "replay") return trStd("padrob", "a replayed command (its nonce was already used)");
    if (code == "too-long") return trStd("padrob", "a field of the command is longer than the centre allows");
    if (code == "busy") return trStd("padrob", "the station took too many commands in the last 30 s; try again shortly");
    if (code == "unknown-tutorial") return trStd("padrob", "the station has no such tutorial");
    if (code == "not-running") return trStd("padrob", "no attempt is running");
    if (code == "not-paused") return trStd("padrob", "the attempt is not paused");
    if (code == "unknown-fault") return trStd("padrob", "no such fault (hose-burst, stuck-valve, worker-in, power-cut)");
    if (code == "unknown-command") return trStd("padrob", "no such command");
    return code;
}

}  // namespace

int runInstructor(const std::vector<std::string>& argsIn)
{
    std::vector<std::string> args = argsIn;
    for (const std::string& a : args) {
        if (a == "--help" || a == "-h") {
            printOut(instructorHelp());
            return kExitOk;
        }
    }
    NetOptions net;
    if (std::string e = takeNet(args, net); !e.empty()) return usageError("instructor", e);
    bool json = false;
    double waitS = 2.0, forS = -1, timeoutS = 5.0, value = std::nan("");
    std::string name = "instructor@" + QSysInfo::machineHostName().toStdString();
    std::vector<std::string> words;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto number = [&](double& out) {
            const auto v = i + 1 < args.size() ? toNumber(args[i + 1]) : std::nullopt;
            if (!v) return false;
            out = *v;
            ++i;
            return true;
        };
        if (a == "--json") {
            json = true;
        } else if (a == "--name" && i + 1 < args.size()) {
            name = args[++i];
        } else if (a == "--wait" || a == "--for" || a == "--timeout" || a == "--value") {
            double v = 0;
            if (!number(v)) return usageError("instructor", fill(trStd("padrob", "%1 needs a number"), {a}));
            (a == "--wait" ? waitS : a == "--for" ? forS : a == "--timeout" ? timeoutS : value) = v;
        } else if (a.rfind("--", 0) == 0) {
            return usageError("instructor", fill(trStd("padrob", "unknown option '%1'"), {a}));
        } else {
            words.push_back(a);
        }
    }
    if (words.empty()) return usageError("instructor", trStd("padrob", "say what to do: list, watch or send"));
    const std::string what = words[0];
    if (what != "list" && what != "watch" && what != "send")
        return usageError("instructor", fill(trStd("padrob", "unknown instructor command '%1'"), {what}));
    if (what == "send" && words.size() < 3) return usageError("instructor", trStd("padrob", "send needs a station and a command"));
    // the key signs the commands and checks what the stations say: without it, nothing is believed
    centre::CentreKey key;
    if (net.keyFile.empty()) {
        return usageError("instructor", trStd("padrob", "the centre's key is required (--key FILE): what the stations "
                                                        "say is signed with it, and so are the commands"));
    }
    {
        QString error;
        const QString keyFile = QString::fromStdString(net.keyFile);
        if (!key.load(keyFile, &error) || !key.isCentreKey(keyFile, &error)) {
            printErr("padrob instructor: " + error.toStdString() + "\n");
            return kExitUsage;
        }
        net.bus.key = key;
    }
    net.bus.node = QString::fromStdString(name);
    auto bus = openBus(net, centre::TopicAnnounce | centre::TopicState | centre::TopicEvent | centre::TopicReply);
    if (!bus) return kExitUsage;
    centre::InstructorNode node(*bus, name, key);
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);

    if (what == "list") {
        const double end = nowS() + waitS;
        while (nowS() < end && !g_stop.load()) {
            bus->wait(20);
            node.poll(nowS());
        }
        if (json) {
            std::string out = "{\"stations\":[";
            bool first = true;
            for (const auto& [n, v] : node.stations()) {
                out += (first ? "" : ",") + stationJson(v);
                first = false;
            }
            printOut(out + "]}\n");
        } else {
            for (const auto& [n, v] : node.stations()) printStation(v);
            if (node.stations().empty()) printOut(trStd("padrob", "no station answered\n"));
        }
        return kExitOk;
    }
    if (what == "watch") {
        std::map<std::string, std::string> presence;
        const double end = forS > 0 ? nowS() + forS : 1e300;
        while (nowS() < end && !g_stop.load()) {
            bus->wait(20);
            node.poll(nowS());
            for (const centre::Event& e : node.takeNewEvents()) {
                printOut(json ? eventJson(e) + "\n" : e.station + " " + fixed(e.t, 2) + " " + e.kind + ": " + e.text + "\n");
            }
            for (const auto& [n, v] : node.stations()) {
                std::string& p = presence[n];
                if (p != v.presence) {
                    p = v.presence;
                    printOut(json ? presenceJson(n, p) + "\n"
                                  : fill(trStd("padrob", "%1 is %2\n"), {n, presenceText(p)}));
                }
            }
            std::fflush(stdout);
        }
        return kExitOk;
    }
    // send: wait for the station to be heard, so the command is not sent before discovery
    const std::string station = words[1], kind = words[2];
    const std::string arg = words.size() > 3 ? words[3] : std::string(), arg2 = words.size() > 4 ? words[4] : std::string();
    const double end = nowS() + timeoutS;
    while (nowS() < end && !node.stations().count(station)) {
        bus->wait(20);
        node.poll(nowS());
    }
    if (!node.stations().count(station)) {
        printErr("padrob instructor: " + fill(trStd("padrob", "station %1 did not answer"), {station}) + "\n");
        return kExitModelErrors;
    }
    // heard is not yet matched: wait until DDS has matched every live station's command
    // reader (a command written before would be lost), then a moment for the station to
    // match this process's reply reader the same way
    auto live = [&] {
        int n = 0;
        for (const auto& [name, v] : node.stations()) n += v.presence == "up" ? 1 : 0;
        return std::max(n, 1);
    };
    while (nowS() < end && bus->commandReaders() < live()) {
        bus->wait(20);
        node.poll(nowS());
    }
    for (const double settle = std::min(end, nowS() + 0.2); nowS() < settle;) {
        bus->wait(20);
        node.poll(nowS());
    }
    const std::uint64_t nonce = node.send(station, kind, arg, arg2, value);
    if (nonce == 0) {
        printErr("padrob instructor: " + bus->lastError().toStdString() + "\n");
        return kExitUsage;
    }
    while (nowS() < end && !node.reply(nonce)) {
        bus->wait(20);
        node.poll(nowS());
    }
    const auto r = node.reply(nonce);
    if (!r) {
        printErr("padrob instructor: " + fill(trStd("padrob", "station %1 did not answer the command"), {station}) + "\n");
        return kExitModelErrors;
    }
    if (json) {
        JsonWriter w(false);
        w.beginObject();
        w.key("station").str(station);
        w.key("command").str(kind);
        w.key("accepted").boolean(r->accepted);
        w.key("reason").str(r->message);
        w.endObject();
        printOut(w.text() + "\n");
    } else {
        printOut(r->accepted ? fill(trStd("padrob", "%1: %2 done\n"), {station, kind})
                             : fill(trStd("padrob", "%1 refused %2: %3\n"), {station, kind, refusalText(r->message)}));
    }
    return r->accepted ? kExitOk : kExitModelErrors;
}

namespace {

/// CPU time of process `pid` so far [s] (Linux /proc), −1 when unknown.
double processCpuS(qint64 pid)
{
    QFile f(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!f.open(QIODevice::ReadOnly)) return -1;
    const QByteArray line = f.readAll();
    const qsizetype close = line.lastIndexOf(')');
    if (close < 0) return -1;
    const QList<QByteArray> fields = line.mid(close + 2).split(' ');
    if (fields.size() < 13) return -1;
    const double ticks = fields[11].toDouble() + fields[12].toDouble();  // utime, stime
    return ticks / double(sysconf(_SC_CLK_TCK));
}

double percentile(std::vector<double> v, double p)
{
    if (v.empty()) return std::nan("");
    std::sort(v.begin(), v.end());
    const std::size_t i = std::min(v.size() - 1, static_cast<std::size_t>(p * double(v.size() - 1) + 0.5));
    return v[i];
}

/// padrob centre key --key CENTRE-KEY --node NAME FILE: node NAME's key, derived from the centre's.
int runCentreNodeKey(std::vector<std::string> args)
{
    std::string centreFile, node, file;
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--key" || a == "--node") {
            if (i + 1 >= args.size()) return usageError("centre", fill(trStd("padrob", "%1 needs a value"), {a}));
            (a == "--key" ? centreFile : node) = args[++i];
        } else if (a.rfind("--", 0) == 0) {
            return usageError("centre", fill(trStd("padrob", "unknown option '%1'"), {a}));
        } else if (file.empty()) {
            file = a;
        } else {
            return usageError("centre", trStd("padrob", "expected: padrob centre key --key CENTRE-KEY --node NAME FILE"));
        }
    }
    if (centreFile.empty() || node.empty() || file.empty()) {
        return usageError("centre", trStd("padrob", "expected: padrob centre key --key CENTRE-KEY --node NAME FILE"));
    }
    centre::CentreKey key;
    QString error;
    if (!key.load(QString::fromStdString(centreFile), &error) || !key.createNodeKey(node, QString::fromStdString(file), &error)) {
        printErr("padrob centre: " + error.toStdString() + "\n");
        return kExitUsage;
    }
    printOut(fill(trStd("padrob", "node %1's key in %2 (fingerprint %3), from the centre key %4\n"),
                  {node, file, key.forNode(node).fingerprint().toStdString(), key.fingerprint().toStdString()}));
    return kExitOk;
}

/// padrob centre seal --key FILE: a secret from standard input, sealed with the centre's key.
int runCentreSeal(std::vector<std::string> args)
{
    NetOptions net;
    if (std::string e = takeNet(args, net); !e.empty()) return usageError("centre", e);
    if (net.keyFile.empty() || args.size() != 1) return usageError("centre", trStd("padrob", "expected: padrob centre seal --key FILE"));
    centre::CentreKey key;
    QString error;
    if (!key.load(QString::fromStdString(net.keyFile), &error)) {
        printErr("padrob centre: " + error.toStdString() + "\n");
        return kExitUsage;
    }
    std::string secret;
    std::getline(std::cin, secret);
    if (!secret.empty() && secret.back() == '\r') secret.pop_back();
    if (secret.empty()) return usageError("centre", trStd("padrob", "give the secret on standard input (one line)"));
    printOut(key.seal(QString::fromStdString(secret)).toStdString() + "\n");
    return kExitOk;
}

/// padrob centre pki DIR [--node NAME]...: the centre's PKI for DDS Security, and node identities.
int runCentrePki(const std::vector<std::string>& args)
{
    std::string dir;
    std::vector<std::string> nodes;
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (args[i] == "--node") {
            if (i + 1 >= args.size()) return usageError("centre", fill(trStd("padrob", "%1 needs a value"), {args[i]}));
            nodes.push_back(args[++i]);
        } else if (args[i].rfind("--", 0) == 0 || !dir.empty()) {
            return usageError("centre", fill(trStd("padrob", "unknown option '%1'"), {args[i]}));
        } else {
            dir = args[i];
        }
    }
    if (dir.empty()) return usageError("centre", trStd("padrob", "expected: padrob centre pki DIR [--node NAME]..."));
    const QString qdir = QString::fromStdString(dir);
    QString error;
    if (nodes.empty() || !QFileInfo::exists(qdir + "/identity_ca.pem")) {
        if (!centre::pki::createCentre(qdir, &error)) {
            printErr("padrob centre: " + error.toStdString() + "\n");
            return kExitUsage;
        }
        printOut(fill(trStd("padrob", "new centre PKI in %1 (identity CA, permissions CA, signed governance)\n"), {dir}));
    }
    for (const std::string& n : nodes) {
        if (!centre::pki::issueNode(qdir, QString::fromStdString(n), &error)) {
            printErr("padrob centre: " + error.toStdString() + "\n");
            return kExitUsage;
        }
        printOut(fill(trStd("padrob", "identity and permissions of node %1 in %2\n"), {n, dir + "/nodes/" + n}));
    }
    return kExitOk;
}

/// padrob centre bench: N headless stations streaming to one instructor on this machine.
int runCentreBench(std::vector<std::string> args)
{
    NetOptions net;
    net.bus = centre::BusOptions::loopback(0);
    if (std::string e = takeNet(args, net); !e.empty()) return usageError("centre", e);
    int stations = 16;
    double seconds = 10, warmup = 3;
    bool json = false;
    std::string tutorial = (paths::tutorialsDir() + "/t0_reach.tut").toStdString();  // the bundled T0
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        const double v = i + 1 < args.size() ? toNumber(args[i + 1]).value_or(std::nan("")) : std::nan("");
        if (a == "--json") {
            json = true;
        } else if (a == "--stations") {
            if (!(v >= 1 && v <= 64 && v == std::floor(v))) return usageError("centre", trStd("padrob", "--stations needs a whole number from 1 to 64"));
            stations = static_cast<int>(v);
            ++i;
        } else if (a == "--seconds") {
            if (!(v > 0)) return usageError("centre", fill(trStd("padrob", "%1 needs a number"), {a}));
            seconds = v;
            ++i;
        } else if (a == "--tutorial" && i + 1 < args.size()) {
            tutorial = args[++i];
        } else {
            return usageError("centre", fill(trStd("padrob", "unknown option '%1'"), {a}));
        }
    }
    if (!QFileInfo::exists(QString::fromStdString(tutorial))) {
        printErr("padrob centre: " + fill(trStd("padrob", "no tutorial file %1 (give --tutorial FILE)"), {tutorial}) + "\n");
        return kExitUsage;
    }
    tutorial = QFileInfo(QString::fromStdString(tutorial)).absoluteFilePath().toStdString();
    const QString dir = QDir::temp().filePath(QStringLiteral("padrob-centre-bench-%1").arg(QCoreApplication::applicationPid()));
    QDir().mkpath(dir);
    const QString keyFile = dir + "/centre.key";
    QString error;
    if (net.keyFile.empty()) {
        if (!centre::CentreKey::create(keyFile, &error)) {
            printErr("padrob centre: " + error.toStdString() + "\n");
            return kExitUsage;
        }
        net.keyFile = keyFile.toStdString();
    }
    centre::CentreKey key;
    if (!key.load(QString::fromStdString(net.keyFile), &error)) {
        printErr("padrob centre: " + error.toStdString() + "\n");
        return kExitUsage;
    }
    net.bus.key = key;
    const std::string prefix = "bench-" + std::to_string(QCoreApplication::applicationPid()) + "-";
    // with DDS Security every node needs an identity: issued here for this run (the PKI's
    // CA keys must be in the folder), removed at the end
    QStringList issued;
    auto removeIssued = [&] {
        for (const QString& n : issued) QDir(net.bus.securityDir + "/nodes/" + n).removeRecursively();
    };
    if (!net.bus.securityDir.isEmpty()) {
        for (int i = 0; i <= stations; ++i) {
            const QString n = QString::fromStdString(prefix + (i == 0 ? std::string("instructor") : std::to_string(i)));
            if (!centre::pki::issueNode(net.bus.securityDir, n, &error)) {
                printErr("padrob centre: " + error.toStdString() + "\n");
                removeIssued();
                return kExitUsage;
            }
            issued << n;
        }
    }
    net.bus.node = QString::fromStdString(prefix + "instructor");
    auto bus = openBus(net, centre::TopicAnnounce | centre::TopicState | centre::TopicEvent | centre::TopicReply);
    if (!bus) {
        removeIssued();
        return kExitUsage;
    }
    centre::InstructorNode node(*bus, "bench-instructor", key);
    // the stations: this same binary, each simulating the tutorial's machine in real time
    std::vector<std::unique_ptr<QProcess>> procs;
    QStringList netArgs{"--domain", QString::number(net.bus.domain), "--key", QString::fromStdString(net.keyFile)};
    for (const QString& i : net.bus.interfaces) netArgs += QStringList{"--interface", i};
    for (const QString& p : net.bus.peers) netArgs += QStringList{"--peer", p};
    if (!net.bus.securityDir.isEmpty()) netArgs += QStringList{"--security", net.bus.securityDir};
    for (int i = 0; i < stations; ++i) {
        auto p = std::make_unique<QProcess>();
        p->setProcessChannelMode(QProcess::ForwardedErrorChannel);
        p->setStandardOutputFile(QProcess::nullDevice());
        p->start(QCoreApplication::applicationFilePath(),
                 QStringList{"station", QString::fromStdString(tutorial), "--name", QString::fromStdString(prefix + std::to_string(i + 1)),
                             "--demo", "--for", QString::number(warmup + seconds + 30)} +
                     netArgs);
        procs.push_back(std::move(p));
    }
    auto stopAll = [&] {
        for (auto& p : procs) p->terminate();
        for (auto& p : procs) {
            if (!p->waitForFinished(5000)) p->kill();
        }
        QDir(dir).removeRecursively();
        removeIssued();
    };
    // every station heard, then each attempt started (the demonstration moves the machine)
    const double heardBy = nowS() + 30;
    auto heard = [&] {
        int n = 0;
        for (const auto& [name, v] : node.stations()) n += v.hasState && name.rfind(prefix, 0) == 0;
        return n;
    };
    while (heard() < stations && nowS() < heardBy) {
        bus->wait(20);
        node.poll(nowS());
    }
    if (heard() < stations) {
        printErr("padrob centre: " + fill(trStd("padrob", "only %1 of %2 stations were heard"), {std::to_string(heard()), std::to_string(stations)}) + "\n");
        stopAll();
        return kExitModelErrors;
    }
    for (const auto& [name, v] : node.stations()) {
        if (name.rfind(prefix, 0) == 0) node.send(name, "start", "", "BENCH");
    }
    const double warmEnd = nowS() + warmup;
    while (nowS() < warmEnd) {
        bus->wait(20);
        node.poll(nowS());
    }
    // the measurement: every state's latency, as the instructor wakes for it
    std::vector<double> latencies;
    std::map<std::string, std::uint64_t> firstSeq, lastSeq;
    std::map<std::string, int> received;
    std::vector<double> cpu0;
    for (auto& p : procs) cpu0.push_back(processCpuS(p->processId()));
    const double self0 = processCpuS(QCoreApplication::applicationPid());
    const double t0 = nowS(), end = t0 + seconds;
    while (nowS() < end) {
        bus->wait(50);
        for (const centre::State& s : bus->takeStates()) {
            latencies.push_back((double(centre::wallUs()) - double(s.sentUs)) / 1000.0);
            if (!firstSeq.count(s.station)) firstSeq[s.station] = s.seq;
            lastSeq[s.station] = s.seq;
            ++received[s.station];
        }
        bus->takeEvents();
        bus->takeAnnounces();
        bus->takeReplies();
    }
    const double wall = nowS() - t0;
    const double selfCpu = (processCpuS(QCoreApplication::applicationPid()) - self0) / wall;
    std::vector<double> stationCpu, rates, lost;
    for (std::size_t i = 0; i < procs.size(); ++i) stationCpu.push_back((processCpuS(procs[i]->processId()) - cpu0[i]) / wall);
    for (const auto& [name, n] : received) {
        rates.push_back(double(n) / wall);
        const double sent = double(lastSeq[name] - firstSeq[name] + 1);
        lost.push_back(sent > 0 ? 1.0 - double(n) / sent : 0.0);
    }
    stopAll();
    const double med = percentile(latencies, 0.5), p99 = percentile(latencies, 0.99), mx = percentile(latencies, 1.0);
    if (json) {
        JsonWriter w(false);
        w.beginObject();
        w.key("stations").integer(stations);
        w.key("seconds").num(wall);
        w.key("states").integer(static_cast<long long>(latencies.size()));
        w.key("rate_hz_median").num(percentile(rates, 0.5));
        w.key("rate_hz_min").num(percentile(rates, 0.0));
        w.key("lost_fraction_max").num(percentile(lost, 1.0));
        w.key("latency_ms_median").num(med);
        w.key("latency_ms_p99").num(p99);
        w.key("latency_ms_max").num(mx);
        w.key("instructor_cpu_percent").num(100 * selfCpu);
        w.key("station_cpu_percent_median").num(100 * percentile(stationCpu, 0.5));
        w.key("cores").integer(QThread::idealThreadCount());
        w.endObject();
        printOut(w.text() + "\n");
    } else {
        printOut(fill(trStd("padrob", "%1 stations streaming to one instructor for %2 s (%3 states):\n"),
                      {std::to_string(stations), fixed(wall, 1), std::to_string(latencies.size())}) +
                 fill(trStd("padrob", "  state rate per station: median %1 Hz, lowest %2 Hz; most lost: %3 %\n"),
                      {fixed(percentile(rates, 0.5), 1), fixed(percentile(rates, 0.0), 1), fixed(100 * percentile(lost, 1.0), 2)}) +
                 fill(trStd("padrob", "  latency, station to instructor: median %1 ms, 99th percentile %2 ms, max %3 ms\n"),
                      {fixed(med, 2), fixed(p99, 2), fixed(mx, 2)}) +
                 fill(trStd("padrob", "  CPU: the instructor %1 % of a core; each station (median) %2 %\n"),
                      {fixed(100 * selfCpu, 1), fixed(100 * percentile(stationCpu, 0.5), 1)}));
    }
    return kExitOk;
}

}  // namespace

int runCentre(const std::vector<std::string>& args)
{
    if (!args.empty() && args[0] == "bench") return runCentreBench(args);
    if (!args.empty() && args[0] == "seal") return runCentreSeal(args);
    if (!args.empty() && args[0] == "pki") return runCentrePki(args);
    if (!args.empty() && args[0] == "key" && args.size() > 2) return runCentreNodeKey(args);
    if (args.size() != 2 || args[0] != "key") {
        if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
            printOut(trStd("padrob", "Usage: padrob centre key FILE\n"
                                     "       padrob centre key --key CENTRE-KEY --node NAME FILE\n"
                                     "       padrob centre seal --key FILE < SECRET\n"
                                     "       padrob centre bench [--stations N] [--seconds S] [--tutorial FILE] [--json]\n"
                                     "       padrob centre pki DIR [--node NAME]...\n"
                                     "\n"
                                     "key: makes a new centre key (32 random bytes) in FILE, readable by its owner only.\n"
                                     "Copy it to every station, instructor and display of the centre (padrob station\n"
                                     "--key, padrob instructor --key, padrob-studio --centre-key): every message is\n"
                                     "signed with it, and what is not is ignored (commands: refused). An existing file\n"
                                     "is never replaced. With --node NAME: node NAME's own key, derived from the\n"
                                     "centre's key, for a station (padrob station --name NAME --key FILE): it signs\n"
                                     "only that station's messages and checks only the commands for it, so the\n"
                                     "station cannot pass for another. Instructors keep the centre's key.\n"
                                     "\n"
                                     "seal: prints the line read from standard input (the records server's password)\n"
                                     "sealed with the centre's key, for padrob station --records-password FILE.\n"
                                     "\n"
                                     "bench: starts N headless stations (default 16) on this computer, each running the\n"
                                     "tutorial's demonstration in real time and streaming its state at 60 Hz, and measures\n"
                                     "at one instructor the state rate, the latency from station to instructor and the CPU\n"
                                     "used (docs/performance.md).\n"
                                     "\n"
                                     "pki: makes the centre's PKI for DDS Security in DIR (an identity CA, a permissions\n"
                                     "CA and the signed governance document); with --node NAME, issues node NAME's\n"
                                     "identity and permissions (valid 10 years) in DIR/nodes/NAME. Copy to each node\n"
                                     "identity_ca.pem, permissions_ca.pem, governance.p7s and its nodes/NAME folder,\n"
                                     "never the .key files of the CAs; then run it with --security DIR.\n"));
            return kExitOk;
        }
        return usageError("centre", trStd("padrob", "expected: padrob centre key FILE"));
    }
    QString error;
    if (!centre::CentreKey::create(QString::fromStdString(args[1]), &error)) {
        printErr("padrob centre: " + error.toStdString() + "\n");
        return kExitUsage;
    }
    centre::CentreKey k;
    k.load(QString::fromStdString(args[1]), &error);
    printOut(fill(trStd("padrob", "new centre key in %1 (fingerprint %2)\n"), {args[1], k.fingerprint().toStdString()}));
    return kExitOk;
}

}  // namespace ide::cli
