#include "acquisition/sim/SimulatedController.h"

#include <arpa/inet.h>
#include <modbus.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

#include "acquisition/modbus/ModbusUrl.h"

namespace driftlab::sim {

// The register map this simulated controller serves is the push's own.
using namespace push;
namespace {

constexpr int kPollIntervalMs = 20;

QString systemError(const QString& what) {
    return QStringLiteral("%1: %2").arg(what, QString::fromLocal8Bit(modbus_strerror(errno)));
}

}  // namespace

SimulatedController::SimulatedController(SimulatedControllerOptions options)
    : m_options(std::move(options)) {}

SimulatedController::~SimulatedController() {
    stop();
    closeAll();
}

std::optional<QString> unusableListenHost(const QString& host) {
    // Looked up before libmodbus, whose IPv4-only server listened on
    // 255.255.255.255 for a name it could not read as an address.
    const auto why = modbus::hostLookupError(host);
    if (!why) return std::nullopt;
    return QStringLiteral("'%1' is neither an IP address nor a host name that resolves (%2)")
        .arg(host, *why);
}

QString SimulatedController::url() const {
    return modbus::ModbusUrl(m_options.host, m_port).toString();
}

bool SimulatedController::start(QString* error) {
    if (m_options.capacity < 2 || m_options.capacity > push::kMaxCapacity) {
        *error = QStringLiteral("capacity %1 is not 2 to %2")
                     .arg(m_options.capacity)
                     .arg(push::kMaxCapacity);
        return false;
    }
    if (const auto why = unusableListenHost(m_options.host)) {
        *error = QStringLiteral("cannot listen on %1").arg(*why);
        return false;
    }
    // The _pi variant listens on IPv6 as well as IPv4 (modbus_new_tcp takes IPv4 only).
    const QByteArray host = m_options.host.toUtf8();
    const QByteArray service = QByteArray::number(m_options.port);
    m_context = modbus_new_tcp_pi(host.constData(), service.constData());
    m_mapping =
        modbus_mapping_new_start_address(0, 0, 0, 0, 0, ControllerRegisters::kRegisterCount, 0, 0);
    if (!m_context || !m_mapping) {
        *error = systemError(QStringLiteral("cannot set up the Modbus server"));
        closeAll();
        return false;
    }
    m_listen = modbus_tcp_pi_listen(m_context, 8);
    if (m_listen == -1) {
        *error =
            systemError(QStringLiteral("%1: cannot listen")
                            .arg(modbus::ModbusUrl(m_options.host, m_options.port).endpoint()));
        closeAll();
        return false;
    }
    sockaddr_storage bound{};
    socklen_t length = sizeof bound;
    getsockname(m_listen, reinterpret_cast<sockaddr*>(&bound), &length);
    m_port = bound.ss_family == AF_INET6 ? ntohs(reinterpret_cast<sockaddr_in6*>(&bound)->sin6_port)
                                         : ntohs(reinterpret_cast<sockaddr_in*>(&bound)->sin_port);
    m_registers = std::make_unique<ControllerRegisters>(
        m_mapping->tab_registers, m_options.capacity, m_options.state, m_options.faults);
    m_registers->setAxisState(m_options.axis);
    m_stop = false;
    m_thread = std::thread([this] { serve(); });
    return true;
}

void SimulatedController::stop() {
    m_stop = true;
    if (m_thread.joinable()) m_thread.join();
}

void SimulatedController::closeAll() {
    if (m_listen != -1) ::close(m_listen);
    m_listen = -1;
    if (m_context) {
        // The sockets are closed by serve(); the context must not close one again.
        modbus_set_socket(m_context, -1);
        modbus_free(m_context);
    }
    m_context = nullptr;
    if (m_mapping) modbus_mapping_free(m_mapping);
    m_mapping = nullptr;
}

void SimulatedController::serve() {
    std::vector<int> clients;
    while (!m_stop) {
        std::vector<pollfd> fds{{m_listen, POLLIN, 0}};
        for (int client : clients) fds.push_back({client, POLLIN, 0});
        const int ready = ::poll(fds.data(), fds.size(), kPollIntervalMs);
        {
            // The controller's scan runs whether or not a request came in.
            std::lock_guard lock(m_mutex);
            m_registers->scan();
        }
        if (ready <= 0) continue;
        for (std::size_t i = 1; i < fds.size(); ++i)
            if (fds[i].revents & (POLLIN | POLLHUP | POLLERR)) handle(fds[i].fd, clients);
        if (fds[0].revents & POLLIN) {
            int listen = m_listen;
            const int client = modbus_tcp_pi_accept(m_context, &listen);
            if (client != -1) clients.push_back(client);
        }
    }
    for (int client : clients) ::close(client);
}

void SimulatedController::handle(int socket, std::vector<int>& clients) {
    const auto drop = [&] {
        ::close(socket);
        clients.erase(std::remove(clients.begin(), clients.end(), socket), clients.end());
    };
    std::uint8_t query[MODBUS_TCP_MAX_ADU_LENGTH];
    modbus_set_socket(m_context, socket);
    const int length = modbus_receive(m_context, query);
    if (length == -1) return drop();  // the client closed or sent garbage
    if (length == 0) return;
    const int header = modbus_get_header_length(m_context);
    const int function = query[header];
    const int address = (query[header + 1] << 8) | query[header + 2];
    const int count = (query[header + 3] << 8) | query[header + 4];
    std::lock_guard lock(m_mutex);
    if (function == MODBUS_FC_WRITE_MULTIPLE_REGISTERS) {
        if (m_registers->dropThisWrite()) return drop();
        if (!m_registers->writable(address, count)) {
            modbus_reply_exception(m_context, query, MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS);
            return;
        }
        if (modbus_reply(m_context, query, length, m_mapping) == -1) return drop();
        m_registers->afterWrite(address, count);
        return;
    }
    if (function != MODBUS_FC_READ_HOLDING_REGISTERS) {
        // The map uses function codes 3 and 16 only.
        modbus_reply_exception(m_context, query, MODBUS_EXCEPTION_ILLEGAL_FUNCTION);
        return;
    }
    m_registers->beforeRead(address, count);
    if (modbus_reply(m_context, query, length, m_mapping) == -1) drop();
}

void SimulatedController::setMachineState(MachineState state) {
    std::lock_guard lock(m_mutex);
    if (m_registers) m_registers->setMachineState(state);
}

void SimulatedController::setAxisState(const devices::AxisState& state) {
    std::lock_guard lock(m_mutex);
    m_options.axis = state;  // kept for a start() still to come
    if (m_registers) m_registers->setAxisState(state);
}

void SimulatedController::setFaults(const ControllerFaults& faults) {
    std::lock_guard lock(m_mutex);
    if (m_registers) m_registers->setFaults(faults);
}

push::TableImage SimulatedController::activeTable() const {
    std::lock_guard lock(m_mutex);
    return m_registers ? m_registers->active() : push::TableImage{};
}

int SimulatedController::writeRequests() const {
    std::lock_guard lock(m_mutex);
    return m_registers ? m_registers->writeRequests() : 0;
}

int SimulatedController::applied() const {
    std::lock_guard lock(m_mutex);
    return m_registers ? m_registers->applied() : 0;
}

std::uint16_t SimulatedController::registerValue(int address) const {
    std::lock_guard lock(m_mutex);
    return m_mapping && address >= 0 && address < ControllerRegisters::kRegisterCount
               ? m_mapping->tab_registers[address]
               : 0;
}

}  // namespace driftlab::sim
