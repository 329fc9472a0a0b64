"""Fixtures of the lab tests: a real ``rig lab`` server (subprocess) and a headless Chromium.

The browser is Debian's chromium driven through Debian's chromedriver (Selenium gets the driver's
path, so Selenium Manager downloads nothing). Without chromium the browser tests skip with the
reason - except in CI (CI=true), where they fail: a browser test skipped in CI does not count.

Screenshots: the browser tests save theirs into $RIG_LAB_SCREENSHOTS when it is set (docs/lab.md
shows the ones taken with RIG_LAB_SCREENSHOTS=docs/figures/lab), else into a temporary folder.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest

CHROMIUM = Path("/usr/bin/chromium")
CHROMEDRIVER = Path("/usr/bin/chromedriver")
EXAMPLE_CLASS = Path(__file__).resolve().parents[2] / "rig" / "lab" / "examples" / "class.toml"
JOIN_CODE = "rolling-2026"  # the example class's
START_LIMIT_S = 10.0  # acceptance 1: the page is served within 10 s of start
WARM_UP_S = 300.0  # the first settle may build the contact table
CHROMIUM_FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--window-size=1000,1800")


class LabServer:
    """A running ``rig lab``: its base URL, output folder and the seconds it took to serve the page."""

    def __init__(self, process: subprocess.Popen, url: str, out_dir: Path, start_s: float) -> None:
        self.process, self.url, self.out_dir, self.start_s = process, url, out_dir, start_s

    def request(self, method: str, path: str, body: object = None, raw: bytes | None = None,
                timeout_s: float = 30.0, token: str | None = None) -> tuple[int, object]:
        """(status, parsed JSON or text) of one request (with the class ``token``, if given)."""
        data = raw if raw is not None else (None if body is None else json.dumps(body).encode())
        headers = {"Content-Type": "application/json"} | ({} if token is None else {"X-Lab-Token": token})
        req = urllib.request.Request(self.url + path.lstrip("/"), data=data, method=method, headers=headers)
        try:
            with urllib.request.urlopen(req, timeout=timeout_s) as response:
                status, text, kind = response.status, response.read().decode(), response.headers.get_content_type()
        except urllib.error.HTTPError as error:
            status, text, kind = error.code, error.read().decode(), error.headers.get_content_type()
        return status, json.loads(text) if kind == "application/json" else text

    def join(self, student: str) -> str:
        """A token for ``student``, joined with the example class's join code."""
        status, answer = self.request("POST", "api/join", {"student": student, "join_code": JOIN_CODE})
        assert status == 201, answer
        return answer["token"]

    @property
    def state_dir(self) -> Path:
        return self.out_dir / "state"

    def teacher_token(self) -> str:
        return (self.state_dir / "teacher-token").read_text().strip()

    def secret(self) -> bytes:
        """The class's secret (the hidden values derive from it)."""
        return bytes.fromhex((self.state_dir / "class-secret").read_text().strip())

    def stop(self) -> None:
        """Stop the server as Ctrl-C does."""
        self.process.send_signal(signal.SIGINT)
        self.process.communicate(timeout=10)


@pytest.fixture(scope="session")
def lab_server(tmp_path_factory):
    """``rig lab --no-browser --port 0`` with the example class, started once for the lab tests."""
    server = start_server(tmp_path_factory.mktemp("lab-sessions"), "--exercises", str(EXAMPLE_CLASS))
    try:
        warm_up(server)
        yield server
    finally:  # also when the warm-up fails: no server left running
        server.stop()


def start_server(out_dir: Path, *extra: str) -> LabServer:
    """``rig lab --no-browser --port 0 -o OUT_DIR`` (and ``extra`` options), serving."""
    command = [sys.executable, "-m", "rig", "lab", "--no-browser", "--port", "0", "-o", str(out_dir), *extra]
    errors = out_dir / "stderr.txt"
    start = time.monotonic()
    with open(errors, "a") as stderr:
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=stderr, text=True)
    line = process.stdout.readline()
    if "serving http://" not in line:
        process.kill()
        process.communicate()
        pytest.fail(f"rig lab did not start: {line!r} {errors.read_text()}")
    url = line.split("serving ")[1].split()[0]
    with urllib.request.urlopen(url, timeout=START_LIMIT_S) as response:
        assert response.status == 200
    return LabServer(process, url, out_dir, time.monotonic() - start)


def warm_up(server: LabServer) -> None:
    """The first settle of each stand builds its contact table (stand A: about 20 s on a busy 2-core
    machine when the disk cache is cold; stand B: one table for the 36 N dead weight, about 25 s;
    then cached): done here, so that no test's timeout pays for it."""
    for stand in ("yoke", "disc_roller"):
        sid = server.request("POST", "api/sessions", {"stand": stand}, timeout_s=WARM_UP_S)[1]["id"]
        status, answer = server.request("POST", f"api/sessions/{sid}/controls", {"settings": {}}, timeout_s=WARM_UP_S)
        assert status == 200, answer


def _chromium_missing() -> str | None:
    missing = [str(p) for p in (CHROMIUM, CHROMEDRIVER) if not p.exists()]
    return f"{' and '.join(missing)} not installed (apt-get install chromium chromium-driver)" if missing else None


@pytest.fixture(scope="session")
def browser():
    """A headless Chromium (fresh profile) driven by Selenium through /usr/bin/chromedriver."""
    reason = _chromium_missing()
    if reason is not None:
        if os.environ.get("CI") == "true":
            pytest.fail(f"CI=true and {reason}: the browser tests must run in CI")
        pytest.skip(reason)
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    profile = tempfile.mkdtemp(prefix="rig-lab-chromium-")
    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM)
    for flag in CHROMIUM_FLAGS + (f"--user-data-dir={profile}",):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(str(CHROMEDRIVER)), options=options)
    yield driver
    driver.quit()
    shutil.rmtree(profile, ignore_errors=True)


@pytest.fixture(scope="session")
def screenshot(tmp_path_factory):
    """shot(driver, name, element_id=None): save the page (or one element of it) as ``name``.png, in a
    64-colour palette to keep the PNGs small."""
    from PIL import Image

    folder = os.environ.get("RIG_LAB_SCREENSHOTS")
    path = Path(folder) if folder else tmp_path_factory.mktemp("lab-screenshots")
    path.mkdir(parents=True, exist_ok=True)

    def shot(driver, name: str, element_id: str | None = None) -> Path:
        target = path / f"{name}.png"
        if element_id is None:
            driver.save_screenshot(str(target))
        else:
            driver.find_element("id", element_id).screenshot(str(target))
        with Image.open(target) as image:
            small = image.convert("RGB").quantize(colors=64)
        small.save(target, optimize=True)
        return target

    return shot
