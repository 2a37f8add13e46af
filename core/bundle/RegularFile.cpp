#include "core/bundle/RegularFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>

namespace driftlab::bundle {
namespace {

QString kindOf(mode_t mode) {
    if (S_ISREG(mode)) return {};
    if (S_ISFIFO(mode)) return QStringLiteral("a FIFO (named pipe)");
    if (S_ISDIR(mode)) return QStringLiteral("a folder");
    if (S_ISCHR(mode)) return QStringLiteral("a character device");
    if (S_ISBLK(mode)) return QStringLiteral("a block device");
    if (S_ISSOCK(mode)) return QStringLiteral("a socket");
    return QStringLiteral("not a file");
}

QString notRegular(const QString& kind) {
    return kind + QStringLiteral(", not a regular file");
}

}  // namespace

QString irregularFileKind(const QString& path) {
    struct stat info;
    if (::stat(QFile::encodeName(path).constData(), &info) != 0) return {};
    return kindOf(info.st_mode);
}

std::unique_ptr<QFile> openRegularFile(const QString& path, QString* error) {
    // O_NONBLOCK: opening a FIFO for reading otherwise waits for a writer.
    const int fd = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        *error = qt_error_string(errno);
        return nullptr;
    }
    struct stat info;
    const bool known = ::fstat(fd, &info) == 0;
    if (!known || !S_ISREG(info.st_mode)) {
        *error = known ? notRegular(kindOf(info.st_mode)) : qt_error_string(errno);
        ::close(fd);
        return nullptr;
    }
    // A regular file never blocks; reads go on as from any file.
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    auto file = std::make_unique<QFile>();
    if (!file->open(fd, QIODevice::ReadOnly, QFileDevice::AutoCloseHandle)) {
        *error = file->errorString();
        ::close(fd);
        return nullptr;
    }
    return file;
}

}  // namespace driftlab::bundle
