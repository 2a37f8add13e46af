#pragma once
// A controller that serves DriftLab's register map over real Modbus TCP
// (libmodbus server on its own thread): for tests, the benchmark, the main job
// and integrators who want to try the map (`driftlab-cli controller-sim`).
// Faults are injected through ControllerFaults. Shutdown is bounded: the
// server thread polls its sockets with a short timeout and checks a stop flag.

#include <QString>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "acquisition/sim/ControllerRegisters.h"

struct _modbus;
struct _modbus_mapping_t;

namespace driftlab::sim {

struct SimulatedControllerOptions {
    QString host = QStringLiteral("127.0.0.1");  ///< an IPv4 or IPv6 address, or a host name
    int port = 0;  ///< 0: a free port chosen by the system (see port())
    int capacity = push::kMaxCapacity;
    MachineState state = MachineState::Idle;
    devices::AxisState axis;  ///< served until setAxisState()
    ControllerFaults faults;
};

/// Why the controller cannot listen on `host` (neither an IP address nor a
/// name that resolves), or nothing.
std::optional<QString> unusableListenHost(const QString& host);

class SimulatedController {
public:
    explicit SimulatedController(SimulatedControllerOptions options = {});
    /// Stops the server (bounded) and closes every connection.
    ~SimulatedController();
    SimulatedController(const SimulatedController&) = delete;
    SimulatedController& operator=(const SimulatedController&) = delete;

    /// Listens and starts serving on its own thread. False with `error`.
    bool start(QString* error);
    /// Stops serving; returns within about one poll interval (20 ms).
    void stop();
    /// The port it listens on, once started.
    int port() const { return m_port; }
    /// modbus://host:port, an IPv6 address in brackets (parseModbusUrl reads it back).
    QString url() const;

    // Thread-safe views and controls for tests and the CLI.
    void setMachineState(MachineState state);
    /// The axis state the controller reports (registers 9…13); the simulated
    /// rig drives it. Encoded as docs/modbus-register-map.md says (0.1 µm,
    /// 0.1 mm/min, 0.01 N·m), saturating at the registers' limits.
    void setAxisState(const devices::AxisState& state);
    /// Replaces the injected faults (a drop counts from now).
    void setFaults(const ControllerFaults& faults);
    push::TableImage activeTable() const;
    /// Write requests received (also the one a drop fault closed on).
    int writeRequests() const;
    /// Tables applied so far.
    int applied() const;
    std::uint16_t registerValue(int address) const;

private:
    void serve();
    void handle(int socket, std::vector<int>& clients);
    void closeAll();

    SimulatedControllerOptions m_options;
    _modbus* m_context = nullptr;
    _modbus_mapping_t* m_mapping = nullptr;
    std::unique_ptr<ControllerRegisters> m_registers;
    mutable std::mutex m_mutex;  ///< guards the registers between the server and callers
    std::thread m_thread;
    std::atomic_bool m_stop{false};
    int m_listen = -1;
    int m_port = 0;
};

}  // namespace driftlab::sim
