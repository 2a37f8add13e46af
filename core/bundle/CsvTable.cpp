#include "core/bundle/CsvTable.h"

#include "core/bundle/ColumnSpelling.h"
#include "core/domain/MessageText.h"

#include <csv.h>
#include <QDateTime>
#include <QHash>
#include <QIODevice>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

namespace driftlab::bundle {
namespace {

constexpr qint64 kChunkBytes = 1 << 20;

extern "C" void onField(void* data, std::size_t size, void* table) {
    static_cast<CsvTable*>(table)->appendField(static_cast<const char*>(data), size);
}
extern "C" void onRecordEnd(int, void* table) {
    static_cast<CsvTable*>(table)->endRecord();
}

/// Only the space pads a field: libcsv's default also counts the tab, which
/// would swallow a tab separator.
extern "C" int isPadding(unsigned char c) {
    return c == CSV_SPACE;
}

}  // namespace

CsvTable::CsvTable(std::unique_ptr<QIODevice> device, const QString& displayName)
    : m_fileName(displayName), m_device(std::move(device)), m_parser(new csv_parser()) {
    // Strict: a quote inside an unquoted field or an unclosed quote is an error,
    // not a silently merged cell.
    if (csv_init(m_parser.get(), CSV_STRICT | CSV_STRICT_FINI) != 0)
        throw BundleException({m_fileName, 0, 0, QStringLiteral("cannot start the CSV parser")});
    // libcsv grows a field's buffer by this much at a time (128 bytes by
    // default: a megabyte-long cell would be copied thousands of times).
    csv_set_blk_size(m_parser.get(), 64 * 1024);
    if (!readRecord())
        throw BundleException(
            {m_fileName, 0, 0, QStringLiteral("missing header line (file is empty)")});
    // A separator closing every line (some exporters write one) leaves an
    // unnamed last column: ignored while it stays empty (next()).
    std::size_t named = m_ends.size();
    if (named > 1 && field(int(named) - 1).empty()) {
        m_trailingSeparator = true;
        --named;
    }
    // A hash, not a scan of the columns before: a header of 100 000 columns
    // would otherwise take half a minute to check.
    QHash<QString, int> columnOf;
    for (std::size_t i = 0; i < named; ++i) {
        std::string_view cell = field(int(i));
        QString name = QString::fromUtf8(cell.data(), qsizetype(cell.size()));
        if (name.isEmpty()) fail(int(i), QStringLiteral("empty column name in header"));
        if (auto it = columnOf.constFind(name); it != columnOf.cend())
            fail(int(i), QStringLiteral("duplicate column %1 in header (also column %2)")
                             .arg(quotedText(name))
                             .arg(*it + 1));
        columnOf.insert(name, int(i));
        m_header.push_back(name);
    }
    // A record with more fields (than the header's, and the trailing
    // separator's) is wrong whatever they hold: stop keeping them.
    m_fieldLimit = m_header.size() + 2;
}

CsvTable::~CsvTable() = default;

void CsvTable::ParserDeleter::operator()(csv_parser* parser) const {
    csv_free(parser);  // its field buffer (a destructor does not run when a constructor throws)
    delete parser;
}

int CsvTable::column(const QString& name) const {
    int found = -1;
    for (std::size_t i = 0; i < m_header.size(); ++i) {
        if (!spellsColumn(m_header[i], name)) continue;
        if (found >= 0)
            throw BundleException({m_fileName, 1, int(i) + 1,
                                   QStringLiteral("columns %1 and %2 both name '%3'")
                                       .arg(quotedText(m_header[std::size_t(found)]),
                                            quotedText(m_header[i]), name)});
        found = int(i);
    }
    return found;
}

int CsvTable::requireColumn(const QString& name) const {
    int c = column(name);
    if (c < 0)
        throw BundleException({m_fileName, 1, 0,
                               QStringLiteral("missing column '%1' in header%2")
                                   .arg(name, sameQuantityInAnotherUnit(name))});
    return c;
}

QString CsvTable::sameQuantityInAnotherUnit(const QString& name) const {
    // "deviation_um" is the quantity "deviation" in um: a header naming
    // "deviation_mm", "deviation [mm]" or a bare "deviation" is the column in
    // another unit, or with none.
    const QString stem = name.left(name.indexOf(QLatin1Char('_')));
    const QString unit = name.mid(stem.size() + 1);
    for (const QString& h : m_header) {
        const std::optional<QString> other = otherUnitOf(h, name);
        if (!other) continue;
        if (other->isEmpty())
            return QStringLiteral(
                       ": it has %1, without its unit (DriftLab reads %2 in %3: "
                       "name it '%4' if it is in %3)")
                .arg(quotedText(h), stem, unit, name);
        return QStringLiteral(
                   ": it has %1, in %2 (DriftLab reads %3 in %4: convert the "
                   "column and name it '%5')")
            .arg(quotedText(h), shownText(*other), stem, unit, name);
    }
    return {};
}

std::vector<int> CsvTable::requireColumns(const QStringList& expected, QStringList& others) const {
    std::vector<int> indices;
    for (const QString& name : expected) indices.push_back(requireColumn(name));
    for (std::size_t i = 0; i < m_header.size(); ++i)
        if (std::find(indices.begin(), indices.end(), int(i)) == indices.end())
            others << m_header[i];
    return indices;
}

std::string_view CsvTable::field(int column) const {
    const std::size_t begin = column == 0 ? 0 : m_ends[std::size_t(column) - 1];
    return std::string_view(m_text).substr(begin, m_ends[std::size_t(column)] - begin);
}

double CsvTable::progress() const {
    const qint64 size = m_device->size();
    return size > 0 ? std::min(1.0, double(m_consumed) / double(size)) : 0.0;
}

void CsvTable::appendField(const char* data, std::size_t size) {
    // libcsv calls this from C: no exception may cross it, so an overlong
    // record is only counted here and refused by next().
    if (m_buildEnds.size() >= m_fieldLimit) {
        ++m_droppedFields;
        return;
    }
    m_buildText.append(data, size);
    m_buildEnds.push_back(m_buildText.size());
}

void CsvTable::endRecord() {
    m_text.swap(m_buildText);
    m_ends.swap(m_buildEnds);
    m_recordFields = m_ends.size() + std::exchange(m_droppedFields, 0);
    m_buildText.clear();
    m_buildEnds.clear();
    m_recordReady = true;
    m_recordLine = m_physicalLine;
}

void CsvTable::detectDelimiter(std::string_view firstLine) {
    // A spreadsheet set to a European locale writes "run;time_s;T_nut" and
    // "20,06": a header with ';' and no ',' can only be that. A header with
    // tabs and neither is a tab-separated export (decimal points).
    const bool comma = firstLine.find(',') != std::string_view::npos;
    if (!comma && firstLine.find(';') != std::string_view::npos) {
        m_delimiter = ';';
    } else if (!comma && firstLine.find('\t') != std::string_view::npos) {
        m_delimiter = '\t';
        csv_set_space_func(m_parser.get(), isPadding);
    }
    csv_set_delim(m_parser.get(), m_delimiter);
}

QString CsvTable::formatNote() const {
    QStringList notes;
    if (m_delimiter == ';')
        notes << QStringLiteral(
            "read as ';'-separated with decimal commas (a spreadsheet's "
            "European export)");
    if (m_delimiter == '\t') notes << QStringLiteral("read as tab-separated");
    if (m_trailingSeparator)
        notes << QStringLiteral(
            "every line ends with a separator: the unnamed, empty last "
            "column is ignored");
    return notes.join(QStringLiteral("; "));
}

bool CsvTable::feedLine() {
    std::size_t newline = m_chunk.find('\n', m_chunkPos);
    while (newline == std::string::npos && !m_atEnd) {
        m_chunk.erase(0, m_chunkPos);
        m_chunkPos = 0;
        const std::size_t old = m_chunk.size();
        m_chunk.resize(old + std::size_t(kChunkBytes));
        const qint64 got = m_device->read(m_chunk.data() + old, kChunkBytes);
        if (got < 0)
            throw BundleException({m_fileName, m_physicalLine + 1, 0,
                                   QStringLiteral("read error: ") + m_device->errorString()});
        m_chunk.resize(old + std::size_t(got));
        if (got == 0) m_atEnd = true;
        if (m_physicalLine == 0 && old == 0 && m_chunk.compare(0, 3, "\xEF\xBB\xBF") == 0)
            m_chunkPos = 3;  // UTF-8 byte-order mark, as spreadsheets write it
        newline = m_chunk.find('\n', std::max(old, m_chunkPos));
    }
    if (m_chunkPos >= m_chunk.size()) return false;
    const std::size_t end = newline == std::string::npos ? m_chunk.size() : newline + 1;
    const std::string_view line(m_chunk.data() + m_chunkPos, end - m_chunkPos);
    if (m_physicalLine == 0) detectDelimiter(line);
    ++m_physicalLine;
    if (csv_parse(m_parser.get(), line.data(), line.size(), onField, onRecordEnd, this) !=
        line.size())
        throw BundleException(
            {m_fileName, m_physicalLine, int(m_buildEnds.size()) + 1,
             QStringLiteral("malformed quoting: a '\"' inside an unquoted field or text after a "
                            "closing quote (RFC 4180 doubles a quote inside a quoted field)")});
    m_chunkPos = end;
    m_consumed += qint64(line.size());
    return true;
}

bool CsvTable::readRecord() {
    m_recordReady = false;
    while (!m_recordReady) {
        if (feedLine()) continue;
        if (csv_fini(m_parser.get(), onField, onRecordEnd, this) != 0)
            throw BundleException(
                {m_fileName, m_physicalLine, int(m_buildEnds.size()) + 1,
                 QStringLiteral("unterminated quoted field: a '\"' is opened and never closed")});
        return m_recordReady;
    }
    return true;
}

bool CsvTable::next() {
    while (readRecord()) {
        if (m_ends.size() == 1 && m_ends[0] == 0) continue;  // a line of spaces
        if (m_trailingSeparator && m_recordFields == m_header.size() + 1) {
            if (!field(int(m_header.size())).empty())
                fail(int(m_header.size()),
                     QStringLiteral("a value under the unnamed last column: %1")
                         .arg(quotedCell(field(int(m_header.size())))));
            m_recordFields = m_header.size();
        }
        if (m_recordFields != m_header.size())
            fail(int(std::min(m_ends.size(), m_header.size())),
                 QStringLiteral("expected %1 fields as in the header, found %2%3")
                     .arg(m_header.size())
                     .arg(m_recordFields)
                     .arg(m_recordFields < m_header.size() ? QStringLiteral(" (truncated line?)")
                                                           : QString()));
        return true;
    }
    return false;
}

double CsvTable::number(int column) const {
    if (field(column).empty())
        fail(column, QStringLiteral("empty cell in column %1").arg(columnName(column)));
    return numberOrMissing(column);
}

double CsvTable::time(int column) const {
    const std::string_view cell = field(column);
    // A date starts with a four-digit year and a '-'; anything else is a number.
    const bool isDate =
        cell.size() >= 10 && cell[4] == '-' &&
        std::all_of(cell.begin(), cell.begin() + 4, [](char c) { return c >= '0' && c <= '9'; });
    if (!isDate) return number(column);
    QString text = QString::fromUtf8(cell.data(), qsizetype(cell.size()));
    if (text.size() > 10 && text[10] == QLatin1Char(' ')) text[10] = QLatin1Char('T');
    const QDateTime read = QDateTime::fromString(text, Qt::ISODateWithMs);
    if (!read.isValid())
        fail(column, QStringLiteral("cell %1 in column %2 is neither a number nor a date and "
                                    "time (ISO 8601: 2026-11-18T11:06:40)")
                         .arg(quotedCell(cell), columnName(column)));
    const bool zoned = read.timeSpec() != Qt::LocalTime;
    const QDateTime utc = zoned ? read.toUTC() : QDateTime(read.date(), read.time(), Qt::UTC);
    return double(utc.toMSecsSinceEpoch()) / 1000.0;
}

double CsvTable::numberOrMissing(int column) const {
    const std::string_view cell = field(column);
    if (cell.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::string_view digits = cell.front() == '+' ? cell.substr(1) : cell;
    char buffer[64];
    if (europeanFormat() && digits.find(',') != std::string_view::npos) {
        if (digits.find('.') != std::string_view::npos || digits.size() >= sizeof buffer)
            fail(column, QStringLiteral("cell %1 in column %2 mixes '.' and ',': thousands "
                                        "separators are not read; export numbers without them")
                             .arg(quotedCell(cell), columnName(column)));
        std::memcpy(buffer, digits.data(), digits.size());
        std::replace(buffer, buffer + digits.size(), ',', '.');
        digits = std::string_view(buffer, digits.size());
    }
    double value = 0;
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range)
        fail(column, QStringLiteral("value %1 in column %2 is out of the range of a number")
                         .arg(quotedCell(cell), columnName(column)));
    if (ec != std::errc() || ptr != digits.data() + digits.size())
        fail(column,
             QStringLiteral("non-numeric cell %1 in column %2%3")
                 .arg(quotedCell(cell), columnName(column),
                      !europeanFormat() && cell.find(',') != std::string_view::npos
                          ? QStringLiteral(" (a decimal comma? use '.' in a ','-separated file)")
                          : QString()));
    if (!std::isfinite(value))
        fail(column, QStringLiteral("NaN or infinite value %1 in column %2")
                         .arg(quotedCell(cell), columnName(column)));
    return value;
}

int CsvTable::integer(int column, int min, int max) const {
    std::string_view cell = field(column);
    int value = 0;
    auto [ptr, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
    const bool whole = !cell.empty() && ptr == cell.data() + cell.size();
    // An integer too large for an int is still an integer: say so, with the range.
    if (whole && (ec == std::errc::result_out_of_range ||
                  (ec == std::errc() && (value < min || value > max))))
        fail(column, QStringLiteral("value %1 in column %2 is out of range: an integer from %3 "
                                    "to %4 is expected")
                         .arg(quotedCell(cell), columnName(column))
                         .arg(min)
                         .arg(max));
    if (!whole || ec != std::errc())
        fail(column, QStringLiteral("expected an integer in column %1, found %2")
                         .arg(columnName(column), quotedCell(cell)));
    return value;
}

QString CsvTable::text(int column) const {
    std::string_view cell = field(column);
    return QString::fromUtf8(cell.data(), qsizetype(cell.size()));
}

QString CsvTable::columnName(int column) const {
    return quotedText(m_header[std::size_t(column)]);
}

void CsvTable::fail(int column, const QString& message) const {
    throw BundleException({m_fileName, m_recordLine, column + 1, message});
}

}  // namespace driftlab::bundle
