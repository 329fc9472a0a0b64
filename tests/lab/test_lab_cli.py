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


def test_a_class_prints_the_teachers_link_and_prepares_its_exercises(tmp_path):
    from tests.lab.conftest import EXAMPLE_CLASS

    process = _start("--port", "0", "-o", str(tmp_path), "--class", str(EXAMPLE_CLASS))
    try:
        lines = [process.stdout.readline() for _ in range(2)]
        token = (tmp_path / "state" / "teacher-token").read_text().strip()
        assert lines[1].startswith("rig lab: teacher's link http://") and f"#teacher={token}" in lines[1]
        assert "join code: rolling-2026" in lines[1] and str(tmp_path / "state" / "tokens.csv") in lines[1]
        progress = [""]
        while progress[-1] != "rig lab: every exercise ready\n":  # one line per exercise
            progress.append(process.stdout.readline())
            assert progress[-1], progress  # not the end of the output before every exercise is ready
        assert sum(line.startswith("rig lab: exercise ") and "ready" in line for line in progress) == 3
    finally:
        process.send_signal(signal.SIGINT)
        process.communicate(timeout=30)


def test_a_bad_class_file_is_one_line_and_exit_2(tmp_path):
    bad = tmp_path / "class.toml"
    bad.write_text('[[exercise]]\nid = "A"\ntitle = "t"\nstand = "yoke"\nmu = [0.3, 0.4]\nfree = []\n')
    process = _start("--port", "0", "-o", str(tmp_path), "--class", str(bad))
    out, err = process.communicate(timeout=60)
    assert process.returncode == 2 and "class" in err and "Traceback" not in err
