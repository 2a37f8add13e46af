"""What the pymodbus peers share: serve one slave context on 127.0.0.1 and
print the port (a free one when asked for 0) for the test that started it."""

import asyncio

from pymodbus.datastore import ModbusServerContext
from pymodbus.server.async_io import ModbusTcpServer


async def serve_on_loopback(slave, port):
    server = ModbusTcpServer(ModbusServerContext(slaves=slave, single=True),
                             address=("127.0.0.1", port), allow_reuse_address=True)
    task = asyncio.create_task(server.serve_forever())
    await server.serving
    print(server.server.sockets[0].getsockname()[1], flush=True)
    await task
