#include "core/bundle/CsvTable.h"

#include <QFile>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

namespace driftlab {
namespace {

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

QString quoted(std::string_view s) {
    return QLatin1Char('\'') + QString::fromUtf8(s.data(), qsizetype(s.size())) + QLatin1Char('\'');
}

}  // namespace

CsvTable::CsvTable(const QString& path, const QString& displayName) : m_fileName(displayName) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw BundleException(
            {m_fileName, 0, 0, QStringLiteral("cannot open: ") + file.errorString()});
    m_data = file.readAll();
    if (m_data.startsWith("\xEF\xBB\xBF")) m_pos = 3;  // UTF-8 byte-order mark

    std::string_view line;
    while (readLine(line)) {
        if (trimmed(line).empty()) continue;
        split(line);
        for (std::size_t i = 0; i < m_fields.size(); ++i) {
            QString name = QString::fromUtf8(m_fields[i].data(), qsizetype(m_fields[i].size()));
            if (name.isEmpty()) fail(int(i), QStringLiteral("empty column name in header"));
            for (std::size_t j = 0; j < i; ++j)
                if (m_header[j] == name)
                    fail(int(i), QStringLiteral("duplicate column '%1' in header (also column %2)")
                                     .arg(name)
                                     .arg(j + 1));
            m_header.push_back(name);
        }
        return;
    }
    throw BundleException(
        {m_fileName, 0, 0, QStringLiteral("missing header line (file is empty)")});
}

int CsvTable::column(const QString& name) const {
    for (std::size_t i = 0; i < m_header.size(); ++i)
        if (m_header[i] == name) return int(i);
    return -1;
}

int CsvTable::requireColumn(const QString& name) const {
    int c = column(name);
    if (c < 0)
        throw BundleException(
            {m_fileName, 1, 0, QStringLiteral("missing column '%1' in header").arg(name)});
    return c;
}

bool CsvTable::readLine(std::string_view& line) {
    if (m_pos >= m_data.size()) return false;
    const char* begin = m_data.constData() + m_pos;
    const char* end =
        static_cast<const char*>(std::memchr(begin, '\n', std::size_t(m_data.size() - m_pos)));
    qsizetype length = end ? end - begin : m_data.size() - m_pos;
    line = std::string_view(begin, std::size_t(length));
    m_pos += length + (end ? 1 : 0);
    ++m_line;
    return true;
}

void CsvTable::split(std::string_view line) {
    m_fields.clear();
    std::size_t start = 0;
    for (;;) {
        std::size_t comma = line.find(',', start);
        std::string_view cell = trimmed(line.substr(start, comma - start));
        if (cell.find('"') != std::string_view::npos)
            fail(int(m_fields.size()), QStringLiteral("quoted fields are not supported"));
        m_fields.push_back(cell);
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
}

bool CsvTable::next() {
    std::string_view line;
    while (readLine(line)) {
        if (trimmed(line).empty()) continue;
        split(line);
        if (m_fields.size() != m_header.size())
            fail(int(std::min(m_fields.size(), m_header.size())),
                 QStringLiteral("expected %1 fields as in the header, found %2%3")
                     .arg(m_header.size())
                     .arg(m_fields.size())
                     .arg(m_fields.size() < m_header.size() ? QStringLiteral(" (truncated line?)")
                                                            : QString()));
        return true;
    }
    return false;
}

double CsvTable::number(int column) const {
    std::string_view cell = field(column);
    if (cell.empty())
        fail(column, QStringLiteral("empty cell in column '%1'").arg(m_header[column]));
    return numberOrMissing(column);
}

double CsvTable::numberOrMissing(int column) const {
    std::string_view cell = field(column);
    if (cell.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::string_view digits = cell.front() == '+' ? cell.substr(1) : cell;
    double value = 0;
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec != std::errc() || ptr != digits.data() + digits.size())
        fail(column, QStringLiteral("non-numeric cell %1 in column '%2'")
                         .arg(quoted(cell), m_header[column]));
    if (!std::isfinite(value))
        fail(column, QStringLiteral("NaN or infinite value %1 in column '%2'")
                         .arg(quoted(cell), m_header[column]));
    return value;
}

int CsvTable::integer(int column) const {
    std::string_view cell = field(column);
    int value = 0;
    auto [ptr, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
    if (cell.empty() || ec != std::errc() || ptr != cell.data() + cell.size())
        fail(column, QStringLiteral("expected an integer in column '%1', found %2")
                         .arg(m_header[column], quoted(cell)));
    return value;
}

QString CsvTable::text(int column) const {
    std::string_view cell = field(column);
    return QString::fromUtf8(cell.data(), qsizetype(cell.size()));
}

void CsvTable::fail(int column, const QString& message) const {
    throw BundleException({m_fileName, m_line, column + 1, message});
}

}  // namespace driftlab
