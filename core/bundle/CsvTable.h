#pragma once
// Minimal, fast reader for the bundle's CSV files: comma separated, one header
// line, no quoting (ids are [A-Za-z0-9_]+ and everything else is a number).
// Fields are views into the file buffer so a million-sample file is parsed
// without per-cell allocation. Every error names file, line and column.

#include <QByteArray>
#include <QString>
#include <string_view>
#include <vector>

#include "core/bundle/BundleError.h"

namespace driftlab {

class CsvTable {
public:
    /// Reads the whole file; throws BundleException if it cannot be read or has no header.
    CsvTable(const QString& path, const QString& displayName);

    const QString& fileName() const { return m_fileName; }
    const std::vector<QString>& header() const { return m_header; }
    /// Index of a header column, or -1.
    int column(const QString& name) const;
    /// Index of a header column; throws naming the file if absent.
    int requireColumn(const QString& name) const;

    /// Advances to the next non-blank record. Throws if its field count differs
    /// from the header's (e.g. a truncated last line).
    bool next();
    int line() const { return m_line; }
    std::string_view field(int column) const { return m_fields[std::size_t(column)]; }
    /// Fraction of the file consumed, for progress reporting.
    double progress() const { return m_data.isEmpty() ? 1.0 : double(m_pos) / m_data.size(); }

    /// A finite number, or throws "non-numeric cell" / "NaN or infinite value".
    double number(int column) const;
    /// Like number() but an empty cell is a missing sample (NaN).
    double numberOrMissing(int column) const;
    int integer(int column) const;
    QString text(int column) const;

    [[noreturn]] void fail(int column, const QString& message) const;

private:
    bool readLine(std::string_view& line);
    void split(std::string_view line);

    QString m_fileName;
    QByteArray m_data;
    qsizetype m_pos = 0;
    int m_line = 0;
    std::vector<QString> m_header;
    std::vector<std::string_view> m_fields;
};

}  // namespace driftlab
