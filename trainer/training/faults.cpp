#include "trainer/training/faults.h"

#include <QCoreApplication>

namespace trainer {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(TutorialSession)
};

}  // namespace

const char* Fault::key(Kind k)
{
    switch (k) {
    case Kind::HoseBurst: return "hose-burst";
    case Kind::StuckValve: return "stuck-valve";
    case Kind::WorkerIn: return "worker-in";
    case Kind::PowerCut: return "power-cut";
    }
    return "?";
}

bool Fault::fromKey(const std::string& key, Kind* k)
{
    for (Kind c : {Kind::HoseBurst, Kind::StuckValve, Kind::WorkerIn, Kind::PowerCut}) {
        if (key == Fault::key(c)) {
            if (k) *k = c;
            return true;
        }
    }
    return false;
}

QString Fault::label(Kind k)
{
    switch (k) {
    case Kind::HoseBurst: return Tr::tr("Hose burst");
    case Kind::StuckValve: return Tr::tr("Stuck valve");
    case Kind::WorkerIn: return Tr::tr("Worker walks in");
    case Kind::PowerCut: return Tr::tr("Power cut");
    }
    return {};
}

}  // namespace trainer
