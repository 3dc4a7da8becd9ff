#include "ide/studio/editor/model_document.h"

#include "solver/pipeline.h"
#include "trainer/io/user_folders.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <QFileSystemWatcher>
#include <QJsonDocument>
#include <QJsonObject>
#include <QPlainTextDocumentLayout>
#include <QSaveFile>
#include <QStringDecoder>
#include <QTextCursor>
#include <QTextDocument>
#include <QTimer>
#include <QUuid>

#include <utility>

namespace studio {

namespace {

QByteArray sha1(const QByteArray& bytes) { return QCryptographicHash::hash(bytes, QCryptographicHash::Sha1); }

QString nativePath(const QString& path) { return QDir::toNativeSeparators(path); }

/// Is `pid` this process, or another running instance of this program? (Linux:
/// /proc/<pid>/exe; a pid reused by another program after a crash does not count.)
bool isLiveSession(qint64 pid)
{
    if (pid <= 0) return false;
    if (pid == QCoreApplication::applicationPid()) return true;
    const QString exe = QFileInfo(QStringLiteral("/proc/%1/exe").arg(pid)).symLinkTarget();
    return !exe.isEmpty() && exe == QFileInfo(QCoreApplication::applicationFilePath()).canonicalFilePath();
}

/// Writes `bytes` to `path` atomically (temporary file + rename).
bool writeAtomically(const QString& path, const QByteArray& bytes, QString& why)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        why = file.errorString();
        return false;
    }
    if (file.write(bytes) != bytes.size()) {
        why = file.errorString();
        file.cancelWriting();
        return false;
    }
    if (!file.commit()) {
        why = file.errorString();
        return false;
    }
    return true;
}

}  // namespace

ModelDocument::ModelDocument(QTextDocument* document, QObject* parent)
    : QObject(parent), m_doc(document), m_untitledKey(QUuid::createUuid().toString(QUuid::WithoutBraces))
{
    if (!m_doc) {
        m_doc = new QTextDocument(this);
        m_doc->setDocumentLayout(new QPlainTextDocumentLayout(m_doc));
    }
    connect(m_doc, &QTextDocument::modificationChanged, this, [this](bool modified) {
        updateRecoveryTimer();
        if (!modified) removeRecovery();  // back to the saved text
        emit modificationChanged(modified);
    });
    connect(m_doc, &QTextDocument::contentsChange, this, [this](int, int removed, int added) {
        if (removed || added) ++m_revision;
    });

    m_watcher = new QFileSystemWatcher(this);
    m_diskCheck = new QTimer(this);
    m_diskCheck->setSingleShot(true);
    m_diskCheck->setInterval(150);  // a program may write a file in several steps
    connect(m_diskCheck, &QTimer::timeout, this, &ModelDocument::checkDisk);
    connect(m_watcher, &QFileSystemWatcher::fileChanged, this, &ModelDocument::scheduleDiskCheck);
    connect(m_watcher, &QFileSystemWatcher::directoryChanged, this, &ModelDocument::scheduleDiskCheck);

    m_recoveryTimer = new QTimer(this);
    connect(m_recoveryTimer, &QTimer::timeout, this, [this] {
        if (m_doc->isModified() && m_revision != m_recoveryRevision) writeRecovery();
    });
}

ModelDocument::~ModelDocument() { removeRecovery(); }

QString ModelDocument::text() const { return m_doc->toPlainText(); }

void ModelDocument::setText(const QString& text)
{
    emit aboutToReplaceText();
    QTextCursor c(m_doc);
    c.beginEditBlock();
    c.select(QTextCursor::Document);
    c.insertText(text);
    c.endEditBlock();
}

QString ModelDocument::displayName() const
{
    return m_path.isEmpty() ? tr("Untitled") : QFileInfo(m_path).fileName();
}

bool ModelDocument::isModified() const { return m_doc->isModified(); }

// ---- files ------------------------------------------------------------------------

bool ModelDocument::readFile(const QString& path, FileText& out, QString* errorMessage) const
{
    auto fail = [&](const QString& message) {
        if (errorMessage) *errorMessage = message;
        return false;
    };
    const QFileInfo info(path);
    const QString shown = nativePath(info.absoluteFilePath());
    if (!info.exists()) return fail(tr("The file “%1” does not exist.").arg(shown));
    if (info.isDir()) return fail(tr("“%1” is a folder, not a model file.").arg(shown));
    if (!info.isFile()) return fail(tr("“%1” is not a regular file.").arg(shown));  // a pipe or a device
    if (info.size() > qint64(solver::kMaxModelFileBytes)) {
        return fail(tr("“%1” is too large for a model file (%2 MB; at most %3 MB).")
                        .arg(shown)
                        .arg(QLocale().toString(double(info.size()) / (1024.0 * 1024.0), 'f', 1))
                        .arg(solver::kMaxModelFileBytes / (1024 * 1024)));
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return fail(tr("Cannot read “%1”: %2.").arg(shown, file.errorString()));
    const QByteArray bytes = file.readAll();
    if (file.error() != QFileDevice::NoError) return fail(tr("Cannot read “%1”: %2.").arg(shown, file.errorString()));
    if (bytes.contains('\0')) return fail(tr("“%1” is not a text file (it contains binary data).").arg(shown));

    out = {};
    out.digest = sha1(bytes);
    out.bom = bytes.startsWith("\xEF\xBB\xBF");
    QStringDecoder utf8(QStringDecoder::Utf8);
    out.text = utf8(bytes);
    if (utf8.hasError()) {
        out.text = QString::fromLatin1(bytes);
        out.latin1 = true;
        out.bom = false;
    }
    out.crlf = out.text.contains(QLatin1String("\r\n"));
    if (out.crlf) out.text.replace(QLatin1String("\r\n"), QLatin1String("\n"));
    return true;
}

bool ModelDocument::writeFile(const QString& path, QString* errorMessage)
{
    auto fail = [&](const QString& message) {
        if (errorMessage) *errorMessage = message;
        return false;
    };
    const QFileInfo info(path);
    const QString shown = nativePath(info.absoluteFilePath());
    const QFileInfo folder(info.absolutePath());
    if (info.isDir()) return fail(tr("Cannot save “%1”: it is a folder.").arg(shown));
    if (!folder.isDir()) {
        return fail(tr("Cannot save “%1”: the folder “%2” does not exist.").arg(shown, nativePath(folder.absoluteFilePath())));
    }
    if (info.exists() && !info.isWritable()) return fail(tr("Cannot save “%1”: the file is read-only.").arg(shown));
    if (!folder.isWritable()) {
        return fail(tr("Cannot save “%1”: the folder “%2” is not writable (permission denied). Save it somewhere else.")
                        .arg(shown, nativePath(folder.absoluteFilePath())));
    }

    QString text = m_doc->toPlainText();
    if (m_crlf) text.replace(QLatin1Char('\n'), QLatin1String("\r\n"));
    QByteArray bytes = text.toUtf8();
    if (m_bom) bytes.prepend("\xEF\xBB\xBF");

    QString why;
    if (!writeAtomically(path, bytes, why)) return fail(tr("Cannot save “%1”: %2.").arg(shown, why));
    m_diskDigest = sha1(bytes);
    m_notifiedDigest.clear();
    m_reportedDeleted = false;
    m_latin1 = false;
    return true;
}

void ModelDocument::newModel(const QString& text)
{
    removeRecovery();
    m_untitledKey = QUuid::createUuid().toString(QUuid::WithoutBraces);
    m_latin1 = m_crlf = m_bom = false;
    m_diskDigest.clear();
    emit aboutToReplaceText();
    m_doc->setPlainText(text);
    m_doc->setModified(false);
    setPath(QString());
}

bool ModelDocument::open(const QString& path, QString* errorMessage)
{
    FileText file;
    if (!readFile(path, file, errorMessage)) return false;
    removeRecovery();
    m_latin1 = file.latin1;
    m_crlf = file.crlf;
    m_bom = file.bom;
    m_diskDigest = file.digest;
    m_notifiedDigest.clear();
    m_reportedDeleted = false;
    emit aboutToReplaceText();
    m_doc->setPlainText(file.text);
    m_doc->setModified(false);
    setPath(QFileInfo(path).absoluteFilePath());
    return true;
}

bool ModelDocument::reload(QString* errorMessage)
{
    if (m_path.isEmpty()) {
        if (errorMessage) *errorMessage = tr("The model has no file to reload.");
        return false;
    }
    FileText file;
    if (!readFile(m_path, file, errorMessage)) return false;
    m_latin1 = file.latin1;
    m_crlf = file.crlf;
    m_bom = file.bom;
    m_diskDigest = file.digest;
    m_notifiedDigest.clear();
    m_reportedDeleted = false;
    setText(file.text);  // undoable: the edits replaced are not lost
    m_doc->setModified(false);
    watch();
    return true;
}

bool ModelDocument::save(QString* errorMessage)
{
    if (m_path.isEmpty()) {
        if (errorMessage) *errorMessage = tr("The model has no file name yet: use Save As.");
        return false;
    }
    // the rename of QSaveFile ends the watch on the old file: watch again after
    unwatch();
    const bool ok = writeFile(m_path, errorMessage);
    if (ok) m_doc->setModified(false);
    watch();
    return ok;
}

bool ModelDocument::saveAs(const QString& path, QString* errorMessage)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    unwatch();
    if (!writeFile(absolute, errorMessage)) {
        watch();
        return false;
    }
    removeRecovery();  // named after the old path
    setPath(absolute);
    m_doc->setModified(false);
    return true;
}

void ModelDocument::setPath(const QString& path)
{
    const bool changed = path != m_path;
    m_path = path;
    watch();
    if (changed) emit filePathChanged(m_path);
}

// ---- watching the file -----------------------------------------------------------

void ModelDocument::unwatch()
{
    const QStringList watched = m_watcher->files() + m_watcher->directories();
    if (!watched.isEmpty()) m_watcher->removePaths(watched);
}

void ModelDocument::watch()
{
    unwatch();
    if (m_path.isEmpty()) return;
    if (QFileInfo::exists(m_path)) {
        m_watcher->addPath(m_path);
    } else {
        // deleted: watch its folder to see it come back
        const QString folder = QFileInfo(m_path).absolutePath();
        if (QFileInfo(folder).isDir()) m_watcher->addPath(folder);
    }
}

void ModelDocument::scheduleDiskCheck() { m_diskCheck->start(); }

void ModelDocument::checkDisk()
{
    if (m_path.isEmpty()) return;
    const QFileInfo info(m_path);
    if (!info.exists()) {
        watch();  // the folder now
        if (!m_reportedDeleted) {
            m_reportedDeleted = true;
            m_notifiedDigest.clear();
            emit fileChangedOnDisk(m_path, true);
        }
        return;
    }
    // a program that saves by renaming a new file over the old one ends the watch
    if (!m_watcher->files().contains(m_path)) watch();
    QFile file(m_path);
    if (!file.open(QIODevice::ReadOnly)) return;  // being written; the next change tells
    const QByteArray digest = sha1(file.readAll());
    const bool wasDeleted = std::exchange(m_reportedDeleted, false);
    if (digest == m_diskDigest && !wasDeleted) return;  // our own save, or touched only
    if (digest == m_notifiedDigest) return;             // already reported
    m_notifiedDigest = digest;
    emit fileChangedOnDisk(m_path, false);
}

// ---- recovery ---------------------------------------------------------------------

QString ModelDocument::recoveryDirectory()
{
    return trainer::userFolders::recovery();
}

QString ModelDocument::recoveryBaseName() const
{
    const QString key = m_path.isEmpty() ? QStringLiteral("untitled:") + m_untitledKey : QStringLiteral("file:") + m_path;
    const QString hash = QString::fromLatin1(sha1(key.toUtf8()).toHex().left(16));
    QString stem = m_path.isEmpty() ? QStringLiteral("untitled") : QFileInfo(m_path).completeBaseName();
    // a readable, portable stem
    for (QChar& c : stem) {
        if (!(c.isLetterOrNumber() || c == u'_' || c == u'-') || c.unicode() > 0x7F) c = u'_';
    }
    return stem.left(40) + u'-' + hash;
}

QString ModelDocument::recoveryFilePath() const { return recoveryDirectory() + u'/' + recoveryBaseName() + QStringLiteral(".pad"); }

bool ModelDocument::writeRecovery(QString* errorMessage)
{
    const QString dir = recoveryDirectory();
    const QString textFile = recoveryFilePath();
    const QString infoFile = dir + u'/' + recoveryBaseName() + QStringLiteral(".json");
    QString why;
    bool ok = QDir().mkpath(dir);
    if (!ok) why = tr("cannot create the folder");
    if (ok) ok = writeAtomically(textFile, m_doc->toPlainText().toUtf8(), why);
    if (ok) {
        QJsonObject info;
        info[QStringLiteral("format")] = QStringLiteral("padrob-recovery-1");
        info[QStringLiteral("path")] = m_path;
        info[QStringLiteral("name")] = displayName();
        info[QStringLiteral("savedAt")] = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
        info[QStringLiteral("pid")] = QCoreApplication::applicationPid();
        ok = writeAtomically(infoFile, QJsonDocument(info).toJson(), why);
    }
    if (!ok) {
        const QString message = tr("Cannot write the recovery copy “%1”: %2.").arg(nativePath(textFile), why);
        if (errorMessage) *errorMessage = message;
        emit recoveryFailed(message);
        return false;
    }
    if (!m_recoveryWritten.isEmpty() && m_recoveryWritten != textFile) {
        QFile::remove(m_recoveryWritten);
        QFile::remove(QFileInfo(m_recoveryWritten).path() + u'/' + QFileInfo(m_recoveryWritten).completeBaseName() +
                      QStringLiteral(".json"));
    }
    m_recoveryWritten = textFile;
    m_recoveryRevision = m_revision;
    emit recoveryWritten(textFile);
    return true;
}

void ModelDocument::removeRecoveryCopy() { removeRecovery(); }

void ModelDocument::removeRecovery()
{
    if (m_recoveryWritten.isEmpty()) return;
    const QFileInfo info(m_recoveryWritten);
    QFile::remove(m_recoveryWritten);
    QFile::remove(info.path() + u'/' + info.completeBaseName() + QStringLiteral(".json"));
    m_recoveryWritten.clear();
}

void ModelDocument::setRecoveryInterval(int ms)
{
    m_recoveryInterval = std::max(0, ms);
    updateRecoveryTimer();
}

void ModelDocument::updateRecoveryTimer()
{
    if (m_recoveryInterval > 0 && m_doc->isModified()) {
        if (!m_recoveryTimer->isActive() || m_recoveryTimer->interval() != m_recoveryInterval) {
            m_recoveryTimer->start(m_recoveryInterval);
        }
    } else {
        m_recoveryTimer->stop();
    }
}

QList<RecoveryEntry> ModelDocument::recoveryEntries()
{
    QList<RecoveryEntry> entries;
    const QDir dir(recoveryDirectory());
    const QFileInfoList files = dir.entryInfoList({QStringLiteral("*.pad")}, QDir::Files, QDir::Time);
    for (const QFileInfo& f : files) {
        RecoveryEntry e;
        e.textFile = f.absoluteFilePath();
        e.infoFile = f.absolutePath() + u'/' + f.completeBaseName() + QStringLiteral(".json");
        e.saved = f.lastModified();
        e.displayName = tr("Untitled");
        QFile infoFile(e.infoFile);
        if (infoFile.open(QIODevice::ReadOnly)) {
            const QJsonObject info = QJsonDocument::fromJson(infoFile.readAll()).object();
            e.originalPath = info.value(QStringLiteral("path")).toString();
            e.displayName = info.value(QStringLiteral("name")).toString(e.displayName);
            const QDateTime at = QDateTime::fromString(info.value(QStringLiteral("savedAt")).toString(), Qt::ISODateWithMs);
            if (at.isValid()) e.saved = at;
            e.processId = info.value(QStringLiteral("pid")).toInteger();
        }
        if (isLiveSession(e.processId)) continue;  // this session's, or another one still running
        entries.append(e);
    }
    return entries;
}

bool ModelDocument::readRecovery(const RecoveryEntry& entry, QString* text, QString* errorMessage)
{
    QFile file(entry.textFile);
    if (!file.open(QIODevice::ReadOnly)) {
        if (errorMessage) {
            *errorMessage = tr("Cannot read the recovery copy “%1”: %2.").arg(nativePath(entry.textFile), file.errorString());
        }
        return false;
    }
    if (text) *text = QString::fromUtf8(file.readAll());
    return true;
}

bool ModelDocument::discardRecovery(const RecoveryEntry& entry)
{
    bool ok = QFile::remove(entry.textFile);
    if (QFileInfo::exists(entry.infoFile)) ok = QFile::remove(entry.infoFile) && ok;
    return ok;
}

bool ModelDocument::restoreRecovery(const RecoveryEntry& entry, QString* errorMessage)
{
    QString text;
    if (!readRecovery(entry, &text, errorMessage)) return false;
    removeRecovery();
    m_latin1 = m_bom = false;
    m_crlf = false;
    m_notifiedDigest.clear();
    m_reportedDeleted = false;
    m_diskDigest.clear();
    const QString path = entry.originalPath.isEmpty() ? QString() : QFileInfo(entry.originalPath).absoluteFilePath();
    if (!path.isEmpty()) {
        // what is on disk now is what a change is measured against
        QFile disk(path);
        if (disk.open(QIODevice::ReadOnly)) {
            const QByteArray bytes = disk.readAll();
            m_diskDigest = sha1(bytes);
            m_crlf = bytes.contains("\r\n");
            m_bom = bytes.startsWith("\xEF\xBB\xBF");
        }
    } else {
        m_untitledKey = QUuid::createUuid().toString(QUuid::WithoutBraces);
    }
    emit aboutToReplaceText();
    m_doc->setPlainText(text);
    setPath(path);
    m_doc->setModified(true);
    // our own copy first, then the old one goes (they may be the same file)
    if (writeRecovery() && QFileInfo(entry.textFile).absoluteFilePath() != QFileInfo(m_recoveryWritten).absoluteFilePath()) {
        discardRecovery(entry);
    }
    return true;
}

}  // namespace studio
