#pragma once
// Streaming reader for the bundle's CSV files on libcsv (RFC 4180: quoted
// fields, doubled quotes, embedded delimiters and line breaks, CRLF). A UTF-8
// byte-order mark is skipped. The file is read in chunks, so memory does not
// grow with the file. A ';'-separated file (the European spreadsheet export) is
// read too, with decimal commas in its numbers, and so is a tab-separated one
// and one whose every line ends with a separator; the caller is told so.
// Every error names file, line and column.

#include <QString>
#include <QStringList>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/bundle/BundleError.h"

class QIODevice;
struct csv_parser;

namespace driftlab::bundle {

class CsvTable {
public:
    /// Reads the header from `device` (opened for reading; the table takes it
    /// over); throws BundleException if it cannot be read or has no header.
    CsvTable(std::unique_ptr<QIODevice> device, const QString& displayName);
    ~CsvTable();
    CsvTable(const CsvTable&) = delete;
    CsvTable& operator=(const CsvTable&) = delete;

    const QString& fileName() const { return m_fileName; }
    const std::vector<QString>& header() const { return m_header; }
    /// Index of a header column, or -1. A format column (time_s) is also
    /// found as other software spells it ("Time [s]": ColumnSpelling.h);
    /// throws when two columns name it.
    int column(const QString& name) const;
    /// Index of a header column; throws naming the file if absent.
    int requireColumn(const QString& name) const;
    /// The indices of these columns, in any order; throws naming a missing
    /// one. The header's further columns go to `others`.
    std::vector<int> requireColumns(const QStringList& expected, QStringList& others) const;
    /// True when the file is ';'-separated with decimal commas.
    bool europeanFormat() const { return m_delimiter == ';'; }
    /// How the file departs from plain ','-separated CSV, as a reader should
    /// be told ("read as tab-separated"), or empty.
    QString formatNote() const;

    /// Advances to the next non-blank record. Throws if its field count differs
    /// from the header's (e.g. a truncated last line) or its quoting is broken.
    bool next();
    /// Line of the current record's end (1-based, counting the header).
    int line() const { return m_recordLine; }
    std::string_view field(int column) const;
    /// Fraction of the file consumed, for progress reporting.
    double progress() const;

    /// A finite number, or throws "non-numeric cell" / "NaN or infinite value".
    double number(int column) const;
    /// Like number() but an empty cell is a missing sample (NaN).
    double numberOrMissing(int column) const;
    /// An integer within [min, max]; throws "expected an integer" or, for one
    /// outside the range (an int's, by default), "out of range" with the range.
    int integer(int column, int min = std::numeric_limits<int>::min(),
                int max = std::numeric_limits<int>::max()) const;
    /// A time in s: a number, or a date and time of day as loggers write them
    /// (ISO 8601, 'T' or a space between: "2026-11-18 11:06:40.5"), read as
    /// seconds since 1970. Without a zone it is read as UTC: only differences
    /// count (a run is counted from its first record), and UTC has no jumps.
    double time(int column) const;
    QString text(int column) const;
    /// The header of `column` as a message quotes it (MessageText.h).
    QString columnName(int column) const;

    [[noreturn]] void fail(int column, const QString& message) const;

    /// libcsv's callbacks (C linkage needs plain functions; not for callers).
    void appendField(const char* data, std::size_t size);
    void endRecord();

private:
    /// For a missing column NAME_UNIT: a hint naming a header column of the
    /// same quantity in another unit or with none; empty if there is none.
    QString sameQuantityInAnotherUnit(const QString& name) const;
    /// Feeds the parser until a record is complete; false at the end of the file.
    bool readRecord();
    bool feedLine();
    void detectDelimiter(std::string_view firstLine);

    /// csv_free()s the parser's buffer too, also when the constructor throws.
    struct ParserDeleter {
        void operator()(csv_parser* parser) const;
    };

    QString m_fileName;
    std::unique_ptr<QIODevice> m_device;
    std::unique_ptr<csv_parser, ParserDeleter> m_parser;
    char m_delimiter = ',';
    bool m_trailingSeparator = false;  ///< the header ends with a separator

    std::string m_chunk;  ///< bytes read but not yet fed
    std::size_t m_chunkPos = 0;
    qint64 m_consumed = 0;  ///< bytes fed so far
    bool m_atEnd = false;
    int m_physicalLine = 0;  ///< lines fed so far

    // The record being assembled and the one handed out (fields as offsets into one buffer).
    std::string m_buildText, m_text;
    std::vector<std::size_t> m_buildEnds, m_ends;
    bool m_recordReady = false;
    std::size_t m_recordFields = 0;      ///< fields of the current record, kept or not
    std::size_t m_fieldLimit = 100'000;  ///< fields kept per record: the header's count + 1
    std::size_t m_droppedFields = 0;
    int m_recordLine = 0;

    std::vector<QString> m_header;
};

}  // namespace driftlab::bundle
