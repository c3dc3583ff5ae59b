"""Debian's headless Chromium driven by selenium, for the tests that need a browser: the
documentation site's (`tests/docs/test_site.py`) and three.js' own renderer
(`tests/crosscheck/test_threejs_chromium.py`)."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from conftest import require, unavailable

CHROMIUM = ("/usr/bin/chromium", "/usr/bin/chromium-browser")
CHROMEDRIVER = ("/usr/bin/chromedriver", "/usr/lib/chromium/chromedriver")
HEADLESS = ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage")


@contextmanager
def chromium(*arguments: str) -> Iterator[Any]:
    """A headless Chromium session with these command-line `arguments` besides the headless
    ones, keeping the console's messages; skipped (failed under CI=true) without Chromium,
    chromedriver or selenium."""
    webdriver: Any = require("selenium.webdriver")
    binary = next((path for path in CHROMIUM if Path(path).exists()), None)
    driver_path = next((path for path in CHROMEDRIVER if Path(path).exists()), None)
    if binary is None or driver_path is None:
        unavailable(
            "Chromium or chromedriver is not installed (apt-get install chromium chromium-driver)"
        )
    options = webdriver.ChromeOptions()
    options.binary_location = binary
    for argument in (*HEADLESS, *arguments):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(options=options, service=webdriver.ChromeService(driver_path))
    driver.set_page_load_timeout(60)
    try:
        yield driver
    finally:
        driver.quit()
