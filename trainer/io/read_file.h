#pragma once
// Reading a file Padrob did not write itself (an input log, a camera path, a station
// profile, an autopilot path, a pending attempt) with the checks every reader gets
// (solver::readTextFile, as for models and tutorials): missing, a folder, not a regular
// file (a device such as /dev/zero, a FIFO that would block, a socket), larger than
// its limit, unreadable. The message is in the current language.

#include "solver/core/diagnostic.h"

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <optional>

namespace trainer {

// The limits, each far above what Padrob writes (a 9-minute T7 demonstration's log is
// 170 kB, its camera path 75 kB; a profile 10 kB) and far below what eats a station PC.
inline constexpr std::uintmax_t kMaxInputLogBytes = 256u << 20;
inline constexpr std::uintmax_t kMaxCameraPathBytes = 64u << 20;
inline constexpr std::uintmax_t kMaxProfileBytes = 1u << 20;
inline constexpr std::uintmax_t kMaxAutopilotPathBytes = 1u << 20;
inline constexpr std::uintmax_t kMaxPendingBytes = 64u << 20;

/// `path` whole, or nullopt with `*error` saying why, without the path (as the readers'
/// parse errors). `fileKind` names what the file should be, with its article;
/// `extension` its usual ending; `tooLargeHint` what to do with one over `maxBytes`.
std::optional<QByteArray> readLimitedFile(const QString& path, std::uintmax_t maxBytes, const solver::Text& fileKind,
                                          const char* extension, const solver::Text& tooLargeHint, QString* error);

/// A solver Text in the current language: the catalogue's translation of each template
/// (as i18n::text, which this library does not link), English without one.
QString translated(const solver::Text& t);

}  // namespace trainer
