#pragma once
// CsvWriter: the output table of `padrob simulate` (and of any other table the
// solver writes): a header line, then rows of numbers, ',' between fields, "\n" at
// the end of each line.
//
// Numbers are written in their shortest round-trip form (std::to_chars: reading the
// text back gives the same double; 0.1 → "0.1", 1 → "1", 1e-05 → "1e-05"), in the C
// locale whatever the process locale; non-finite values as "nan", "inf", "-inf".
// Header names that hold ',', '"' or a line end are quoted ("" for a quote).
//
// To a file, through an OutputFile (solver/core/output_file.h): never onto a file the
// run reads, into a temporary file in the target's folder (unnamed where the file system
// allows) put in the target's place in commit(), after an fsync; a writer destroyed
// without a successful commit() — an error, an exception, an early return, a killed
// process — leaves the target as it was (absent, or its old contents) and no temporary
// file. Nothing is ever half-written at the target's path. A target that is not a
// regular file (/dev/null, a FIFO) is written into as a stream.
// To standard output, rows go out as they are written and commit() flushes.
//
// Errors (cannot create, write or rename) put the writer in a failed state: later
// writes do nothing, commit() returns false, errorString() says why (errorText(), the
// same translatable). No exceptions.
// Writing a row does not allocate once the first row of the widest length is written.

#include "solver/core/diagnostic.h"
#include "solver/core/output_file.h"

#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace solver {

class CsvWriter {
public:
    /// A writer to standard output.
    CsvWriter();
    /// A writer to the file `path`: creates the temporary file now (check ok()); refused
    /// when `path` is one of `inputs` (the files the run reads).
    explicit CsvWriter(std::string path, const std::vector<std::string>& inputs = {});
    /// Removes the temporary file unless commit() succeeded.
    ~CsvWriter();

    CsvWriter(const CsvWriter&) = delete;
    CsvWriter& operator=(const CsvWriter&) = delete;

    /// False after any error.
    bool ok() const { return m_error.empty(); }
    /// Why the writer failed, e.g. "cannot create out.csv: No such file or directory";
    /// empty while ok().
    const std::string& errorString() const { return m_error; }
    /// The same, translatable (context "Diagnostics"): errorText().english() == errorString().
    const Text& errorText() const { return m_errorText; }
    /// True when writing to standard output.
    bool toStdout() const { return m_path.empty(); }
    /// The target path (empty for standard output).
    const std::string& path() const { return m_path; }
    /// The named temporary file's path while it exists (empty for standard output, for
    /// an unnamed temporary file, and after commit or abandon).
    const std::string& temporaryPath() const { return m_out.temporaryPath(); }

    /// Writes the header line; sets the number of columns every row must have.
    void writeHeader(std::span<const std::string> names);
    /// Writes one row; its length must be the header's (otherwise the writer fails).
    void writeRow(std::span<const double> values);

    /// Row by parts: add() each value, then endRow().
    void add(double value);
    void endRow();

    /// Rows written so far.
    long long rowCount() const { return m_rows; }

    /// Flushes and closes the file and renames it onto the target (file), or flushes
    /// standard output. Returns ok(). After commit() the writer takes no more rows.
    bool commit();
    /// Closes and removes the temporary file without touching the target.
    void abandon();

private:
    void fail(Text message);
    void appendNumber(double value);
    void flushLine();

    std::string m_path;
    OutputFile m_out;
    std::FILE* m_file = nullptr;  // stdout, or m_out's stream
    std::string m_line;  // the line being built (capacity reused)
    std::string m_error;
    Text m_errorText;
    long long m_rows = 0;
    std::size_t m_columns = 0;      // from the header; 0 = no header yet
    std::size_t m_inRow = 0;        // values added to the current row
    bool m_committed = false;
};

}  // namespace solver
