#pragma once
// InputTable: the operator commands of `padrob simulate --input FILE.csv`.
//
// Format (docs/cli.md): a header line naming the columns, then one row per time.
// - Columns: `t` (time [s]) and `u<joint id>` (e.g. `u2`), the command of that joint's
//   drive, a valve spool position or joystick axis in [−1, 1]. Names are
//   case-insensitive (`T`, `U2`); `u02` is joint 2. Each column at most once, in any
//   order; `t` is required.
// - Fields are separated by ',' (or by ';' when the header has ';' and no ','),
//   blanks around a field are ignored, a field may be in double quotes ("" inside is a
//   quote). Numbers are in the C locale: '.' is the decimal point (`0.5`, `-.25`,
//   `1e-3`); no decimal comma, no NaN or infinity.
// - Rows: one value per column; times strictly increasing. Blank lines are ignored;
//   a UTF-8 byte order mark and "\r\n" line ends are accepted.
// - Values hold from their row's time until the next row's (zero-order hold) and
//   after the last row. Before the first row's time every command is 0 (valves closed).
//
// Every problem is a Diagnostic (code, file:line:column, message, hint); all of them
// are reported, not only the first. Lines and columns are 1-based, columns count
// characters (code points).

#include "solver/core/diagnostic.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace solver {

class InputTable {
public:
    /// Parses CSV text. Errors go to `diags` (whose file() names the file in them);
    /// nullopt when there was any error.
    static std::optional<InputTable> parse(std::string_view text, Diagnostics& diags);
    /// Reads and parses a file. An unreadable, missing or too large file (a folder)
    /// gives one "io-error" diagnostic without position. Sets diags' file to `path`
    /// when it has none.
    static std::optional<InputTable> readFile(const std::string& path, Diagnostics& diags);

    /// Number of command columns (`u…`; the `t` column is not counted).
    std::size_t columnCount() const { return m_jointIds.size(); }
    /// Modeler's joint id of command column `column`, in the header's order.
    int jointId(std::size_t column) const { return m_jointIds[column]; }
    /// The column of joint `jointId`'s command, or nullopt.
    std::optional<std::size_t> column(int jointId) const;
    /// The column's name as written in the header (e.g. "u2").
    const std::string& columnName(std::size_t column) const { return m_names[column]; }
    /// Where the column's name is in the header.
    SourcePos columnPos(std::size_t column) const { return m_namePos[column]; }
    /// Where the header line starts.
    SourcePos headerPos() const { return m_headerPos; }

    std::size_t rowCount() const { return m_times.size(); }
    double time(std::size_t row) const { return m_times[row]; }  ///< [s]
    double at(std::size_t row, std::size_t column) const
    {
        return m_values[row * columnCount() + column];
    }

    /// The command of `column` at time t [s] (zero-order hold; 0 before the first
    /// row). Binary search: O(log rows). No allocation.
    double value(std::size_t column, double t) const;

    /// The row in force at t: the last row whose time is ≤ t, or nullopt before the first.
    std::optional<std::size_t> rowAt(double t) const;

    /// Per-step lookup: remembers the row in force, so that a sequence of increasing
    /// times costs O(1) per step on average (any time may be asked; going back
    /// searches again). Points to its table, which must stay where it is while the
    /// cursor is used (take the cursor from the table's final home). No allocation.
    class Cursor {
    public:
        explicit Cursor(const InputTable& table) : m_table(&table) {}
        /// Moves to the row in force at t [s].
        void seek(double t);
        /// The command of `column` at the time of the last seek (0 before the first row).
        double value(std::size_t column) const
        {
            return m_row < 0 ? 0.0 : m_table->at(static_cast<std::size_t>(m_row), column);
        }
        /// The row in force, −1 before the first row.
        std::ptrdiff_t row() const { return m_row; }

    private:
        const InputTable* m_table;
        std::ptrdiff_t m_row = -1;
    };

    Cursor cursor() const { return Cursor(*this); }

private:
    std::vector<int> m_jointIds;
    std::vector<std::string> m_names;
    std::vector<SourcePos> m_namePos;
    SourcePos m_headerPos{1, 1};
    std::vector<double> m_times;
    std::vector<double> m_values;  ///< row-major, rowCount × columnCount
};

/// Checks the table's columns against a model: every column must name a joint
/// (`jointIds`: the ids of all the model's joints) that has a drive (`drivenJoints`:
/// the ids of the joints whose drive takes a command), and every driven joint must
/// have a column. Errors: "unknown-joint" and "no-drive" at the column's name;
/// "missing-column" at the start of the header line. Returns true when all is well.
/// The caller says which joints take a command (e.g. none under `simulate --passive`).
bool checkInputColumns(const InputTable& table, std::span<const int> drivenJoints,
                       std::span<const int> jointIds, Diagnostics& diags);

/// Largest input file read, in bytes.
inline constexpr std::size_t kMaxInputFileBytes = 512u * 1024u * 1024u;

}  // namespace solver
