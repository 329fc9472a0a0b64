"""``rig lab`` on the command line: serves quickly, stops cleanly on Ctrl-C, names a bad port."""

from __future__ import annotations

import signal
import socket
import subprocess
import sys
import time
import urllib.request

from tests.lab.conftest import START_LIMIT_S


def _start(*args: str) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "rig", "lab", "--no-browser", *args],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def test_ctrl_c_stops_the_server_cleanly(tmp_path):
    start = time.monotonic()
    process = _start("--port", "0", "-o", str(tmp_path))
    url = process.stdout.readline().split("serving ")[1].split()[0]
    with urllib.request.urlopen(url, timeout=START_LIMIT_S) as response:
        assert b"friction-rig virtual lab" in response.read()
    assert time.monotonic() - start < START_LIMIT_S
    process.send_signal(signal.SIGINT)
    out, err = process.communicate(timeout=10)
    assert process.returncode == 0, err
    assert "rig lab: stopped" in out and "Traceback" not in err


def test_a_port_in_use_is_a_named_error(tmp_path):
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        process = _start("--port", str(taken.getsockname()[1]), "-o", str(tmp_path))
        out, err = process.communicate(timeout=30)
    assert process.returncode == 2
    assert "--port" in err and "Traceback" not in err
