#pragma once
// ModelDocument: a `.pad` file being edited — its text (a QTextDocument, usually
// the CodeEditor's), its path, and the things that keep text from being lost:
//  - open/save/saveAs/reload with clear error messages; saving goes through
//    QSaveFile, so a failed save never truncates or half-writes the old file;
//  - the modified flag is the QTextDocument's (undo back to the saved text clears
//    it); undo/redo are the document's;
//  - a QFileSystemWatcher reports a file changed or deleted by another program
//    (fileChangedOnDisk); our own saves are not reported;
//  - while modified, a recovery copy of the text is written every
//    recoveryInterval() ms to <AppDataLocation>/recovery/<name>-<hash>.pad, with a
//    JSON side file (<…>.json: the original path, time, process id). It is
//    removed on save, when the text is back to the saved one, on newModel/open,
//    and when the document is destroyed (a normal close); a crash leaves it, and
//    the next session lists it with recoveryEntries() and restores it.
// Text is read as UTF-8 (Latin-1 when it is not valid UTF-8, as the solver does)
// and written as UTF-8; CRLF line ends and a byte-order mark are kept as found.

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QObject>
#include <QString>

class QFileSystemWatcher;
class QTextDocument;
class QTimer;

namespace studio {

/// A recovery copy left on disk (by a session that crashed).
struct RecoveryEntry {
    QString textFile;      ///< the recovered text (UTF-8)
    QString infoFile;      ///< its side file (JSON); may be missing
    QString originalPath;  ///< the model's file; "" for a model never saved
    QString displayName;   ///< the file's name, or "Untitled"
    QDateTime saved;       ///< when the copy was written
    qint64 processId = 0;  ///< the session that wrote it
};

class ModelDocument : public QObject {
    Q_OBJECT
public:
    /// Default interval between recovery copies [ms].
    static constexpr int kDefaultRecoveryIntervalMs = 30000;

    /// Manages `document` (for instance a CodeEditor's, which must outlive this
    /// object), or a document of its own when null. Starts untitled and empty.
    explicit ModelDocument(QTextDocument* document = nullptr, QObject* parent = nullptr);
    /// Removes the recovery copy (a normal close; the main window asked first).
    ~ModelDocument() override;

    QTextDocument* textDocument() const { return m_doc; }
    QString text() const;
    /// Replaces the whole text as one undoable edit (the document becomes modified).
    void setText(const QString& text);

    /// An untitled document with `text` (not modified); the undo history is cleared.
    void newModel(const QString& text = {});
    /// Reads `path` (absolute or relative to the working folder). On failure the
    /// document is unchanged and `errorMessage` says why.
    bool open(const QString& path, QString* errorMessage = nullptr);
    /// Writes the text to filePath(); fails for an untitled document.
    bool save(QString* errorMessage = nullptr);
    /// Writes the text to `path`, which becomes filePath() on success.
    bool saveAs(const QString& path, QString* errorMessage = nullptr);
    /// Reads filePath() again; the replaced text stays in the undo history.
    bool reload(QString* errorMessage = nullptr);

    /// Absolute path of the file, "" when untitled.
    QString filePath() const { return m_path; }
    bool isUntitled() const { return m_path.isEmpty(); }
    /// The file's name ("pendulum.pad") or "Untitled": for the window title.
    QString displayName() const;
    bool isModified() const;
    /// True when the file last read was not UTF-8 and was read as Latin-1 (it will
    /// be saved as UTF-8).
    bool readAsLatin1() const { return m_latin1; }

    // ---- recovery -------------------------------------------------------------
    /// Interval between recovery copies while modified [ms]; 0 turns them off.
    void setRecoveryInterval(int ms);
    int recoveryInterval() const { return m_recoveryInterval; }
    /// Where this document's recovery copy goes (it may not exist).
    QString recoveryFilePath() const;
    /// Writes the recovery copy now (also when not modified).
    bool writeRecovery(QString* errorMessage = nullptr);
    /// Deletes this document's recovery copy: the modeler chose not to keep the
    /// changes (the main window calls it when closing). A later edit writes anew.
    void removeRecoveryCopy();
    /// Takes a recovery copy's text and file path; the document is modified (the
    /// text is not saved yet). The entry's files are removed once this document has
    /// written its own copy.
    bool restoreRecovery(const RecoveryEntry& entry, QString* errorMessage = nullptr);

    /// The folder of recovery copies: <AppDataLocation>/recovery.
    static QString recoveryDirectory();
    /// Recovery copies left by sessions that ended without saving (a crash), newest
    /// first; not those of this process or of another running instance.
    static QList<RecoveryEntry> recoveryEntries();
    static bool readRecovery(const RecoveryEntry& entry, QString* text, QString* errorMessage = nullptr);
    /// Deletes an entry's files.
    static bool discardRecovery(const RecoveryEntry& entry);

signals:
    void modificationChanged(bool modified);
    /// The whole text is about to be replaced (newModel, open, reload, setText,
    /// restore): marks on the old text can go first.
    void aboutToReplaceText();
    /// The file path changed (open, saveAs, newModel, restore): update the title.
    void filePathChanged(const QString& path);
    /// Another program changed (deleted == false) or deleted the file. Reported once
    /// per new content; the main window asks whether to reload().
    void fileChangedOnDisk(const QString& path, bool deleted);
    void recoveryWritten(const QString& textFile);
    /// A recovery copy could not be written (a full disk …).
    void recoveryFailed(const QString& message);

private:
    struct FileText {
        QString text;
        QByteArray digest;
        bool latin1 = false, crlf = false, bom = false;
    };
    bool readFile(const QString& path, FileText& out, QString* errorMessage) const;
    bool writeFile(const QString& path, QString* errorMessage);
    void setPath(const QString& path);
    void watch();
    void unwatch();
    void scheduleDiskCheck();
    void checkDisk();
    void removeRecovery();
    void updateRecoveryTimer();
    QString recoveryBaseName() const;

    QTextDocument* m_doc = nullptr;
    QString m_path;
    QString m_untitledKey;  // names an untitled document's recovery copy
    bool m_latin1 = false, m_crlf = false, m_bom = false;

    QFileSystemWatcher* m_watcher = nullptr;
    QTimer* m_diskCheck = nullptr;
    QByteArray m_diskDigest;      // SHA-1 of the bytes last read or written
    QByteArray m_notifiedDigest;  // of the last change reported
    bool m_reportedDeleted = false;

    QTimer* m_recoveryTimer = nullptr;
    int m_recoveryInterval = kDefaultRecoveryIntervalMs;
    quint64 m_revision = 0;          // counts text changes
    quint64 m_recoveryRevision = 0;  // the revision of the last copy written
    QString m_recoveryWritten;       // the copy on disk ("" = none)
};

}  // namespace studio
