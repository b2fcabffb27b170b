"""The LPE explorer page in a real browser: Debian's chromium, headless, driven through
Debian's chromedriver by Selenium (pinned in .ci/browser-requirements.txt).

Starts `lpe-check serve --port 0`, loads the page and does what a person would: types an
expression with an error and reads the caret message, types a valid list and finds the
automaton drawn and the partition table, types a path and finds its trace highlighted on
the drawing, compares two lines, finds the size of a set too large to draw, switches the language. Then writes a report with `lpe-check report` and opens
it from a file:// URL with the network off, checking that the page asks for nothing
but its own file. A screenshot of each step goes to target/explorer/*.png.

Faults caught: the page leaving the selected language out of its requests; only the
current vertex of a trace highlighted (not the path up to it).

    python3 tests/browser/explorer.py [path/to/lpe-check]

(tests/browser/README.md says how to set it up; .ci/run runs it.)
"""

import glob
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import traceback

from selenium import webdriver
from selenium.common.exceptions import TimeoutException
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select, WebDriverWait

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
OUT = os.path.join(ROOT, "target", "explorer")
CHROMIUM = os.environ.get("CHROMIUM", "/usr/bin/chromium")
CHROMEDRIVER = os.environ.get("CHROMEDRIVER", "/usr/bin/chromedriver")
WAIT = 20  # seconds for any one thing to appear: the page answers in milliseconds

LIST = (
    "diffuse = C<RD>.*[<L.>O]\n"
    "specular = C<RS>.*[<L.>O]\n"
    "transmission = C<T.>.*[<L.>O]"
)


def start_server(lpe_check):
    """`lpe-check serve --port 0`, and the URL it prints."""
    server = subprocess.Popen(
        [lpe_check, "serve", "--port", "0"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    line = server.stdout.readline()
    if "http://" not in line:
        server.kill()
        raise RuntimeError("lpe-check serve printed no URL: %r %s" % (line, server.stderr.read()))
    url = line[line.index("http://"):].split()[0]
    return server, url


def browser(user_data_dir):
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in [
        "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
        "--disable-background-networking", "--disable-component-update", "--disable-sync",
        "--user-data-dir=" + user_data_dir, "--window-size=1200,1000",
    ]:
        options.add_argument(flag)
    # Every request the browser makes is in the performance log (CDP Network events).
    options.set_capability("goog:loggingPrefs", {"performance": "ALL"})
    return webdriver.Chrome(options=options, service=Service(CHROMEDRIVER))


def wait_for(driver, what, condition):
    try:
        return WebDriverWait(driver, WAIT, poll_frequency=0.05).until(lambda d: condition(d))
    except TimeoutException:
        raise AssertionError("waited %d s for %s" % (WAIT, what)) from None


def type_into(driver, element_id, text):
    """Replaces a box's text by typing, as a person would (each key an input event)."""
    box = driver.find_element(By.ID, element_id)
    box.click()
    box.send_keys(Keys.CONTROL, "a")
    box.send_keys(Keys.DELETE)
    box.send_keys(text)


def texts(driver, selector):
    return [e.text for e in driver.find_elements(By.CSS_SELECTOR, selector)]


def shot(driver, name):
    driver.save_screenshot(os.path.join(OUT, name + ".png"))


def requests_made(driver):
    """The URLs of every request in the performance log since it was last read."""
    urls = []
    for entry in driver.get_log("performance"):
        message = json.loads(entry["message"])["message"]
        if message["method"] == "Network.requestWillBeSent":
            urls.append(message["params"]["request"]["url"])
    return urls


def step_error_caret(driver, url):
    driver.get(url)
    wait_for(driver, "the page to start", lambda d: d.find_element(By.TAG_NAME, "body").get_attribute("data-ready") == "true")
    type_into(driver, "aovs", "diffuse = C<RD>L\nbad = C<RD")
    diag = wait_for(driver, "the error under line 2", lambda d: d.find_elements(By.CSS_SELECTOR, '#diagnostics .diag[data-line="2"]'))[0]
    assert "unclosed `<`" in diag.find_element(By.CSS_SELECTOR, ".message").text, diag.text
    caret = diag.find_element(By.CSS_SELECTOR, "pre.caret").text
    # The caret sits under the `<` of `C<RD`, character 8 of `bad = C<RD`.
    assert caret.split("\n") == ["bad = C<RD", "       ^"], repr(caret)
    shot(driver, "1-error")


def step_drawing_and_partition(driver):
    type_into(driver, "aovs", LIST)
    wait_for(driver, "the list to parse", lambda d: "Every line parses" in d.find_element(By.ID, "diagnostics").text)
    states = wait_for(driver, "states in the drawing", lambda d: d.find_elements(By.CSS_SELECTOR, '.graph svg [id^="s"]'))
    assert len(states) >= 2, len(states)
    wait_for(driver, "edges in the drawing", lambda d: d.find_elements(By.CSS_SELECTOR, '.graph svg [id^="e"]'))
    rows = wait_for(driver, "the partition table", lambda d: d.find_elements(By.CSS_SELECTOR, ".partition table tbody tr"))
    table = driver.find_element(By.CSS_SELECTOR, ".partition").text
    # The three AOVs leave camera-to-light paths with no bounce (`C L`) uncovered.
    assert "gap" in table and "C L" in table, table
    assert len(rows) >= 1
    canonical = driver.find_element(By.ID, "canonical").text
    assert "diffuse" in canonical and "transmission" in canonical, canonical
    shot(driver, "2-drawing")


def step_trace(driver):
    """`C RD1 L` through the list's automaton: the start s0, `C` to s1, `RD1` to s2 (the
    diffuse branch), `L` to s5 (diffuse's accepting state); states are numbered
    breadth-first, so these ids are fixed by the list."""
    type_into(driver, "path", "C RD1 L")
    want = {"s0", "e0-1", "s1", "e1-2", "s2", "e2-5", "s5"}
    lit = lambda d: {e.get_attribute("id") for e in d.find_elements(By.CSS_SELECTOR, ".graph svg .lpe-trace")}
    wait_for(driver, "the trace highlighted", lambda d: lit(d) == want or None)
    current = lambda d: {e.get_attribute("id") for e in d.find_elements(By.CSS_SELECTOR, ".graph svg .lpe-current")}
    assert current(driver) == {"e2-5", "s5"}, current(driver)
    assert "Lands in diffuse" in driver.find_element(By.ID, "explain").text
    shot(driver, "3-trace")
    # One vertex back: the trace ends at s2, reached by RD1.
    driver.find_element(By.ID, "step-prev").click()
    assert current(driver) == {"e1-2", "s2"}, current(driver)
    assert lit(driver) == {"s0", "e0-1", "s1", "e1-2", "s2"}, lit(driver)
    driver.find_element(By.ID, "step-next").click()


def step_equivalence(driver):
    type_into(driver, "left", "diffuse")
    type_into(driver, "right", "C<RD>.*[<L.>O]")
    wait_for(driver, "the equivalent verdict", lambda d: "equivalent:" in d.find_element(By.ID, "equiv").text)
    type_into(driver, "right", "C<RD>[<L.>O]")
    wait_for(driver, "the distinguishing path", lambda d: "distinguishing path" in d.find_element(By.ID, "equiv").text)
    shot(driver, "4-equivalence")


def step_too_large(driver):
    """`C.*<RD>.{6}L` compiles to 130 states whose layout needs 5 341 nodes, over the
    drawing's limit: the page says so with the size instead of a drawing."""
    type_into(driver, "aovs", "big = C.*<RD>.{6}L")
    note = wait_for(driver, "the too-large note", lambda d: d.find_elements(By.CSS_SELECTOR, ".graph .too-large"))[0]
    assert "too large to draw: 130 states" in note.text, note.text
    assert not driver.find_elements(By.CSS_SELECTOR, ".graph svg")


def step_language(driver):
    """`C<R[GS]>.*[LO]` is OSL's (G: glossy), an error in RenderMan's dialect: the
    selector's choice reaches the API, for a dialect and for a renderer's profile."""
    language = Select(driver.find_element(By.ID, "language"))
    type_into(driver, "aovs", "glossy = C<R[GS]>.*[LO]")
    wait_for(driver, "RenderMan's error on G", lambda d: "unexpected character `G`" in d.find_element(By.ID, "diagnostics").text)
    for choice in ["dialect:osl", "renderer:karma"]:
        language.select_by_value(choice)
        wait_for(driver, "the line to parse as " + choice, lambda d: "Every line parses" in d.find_element(By.ID, "diagnostics").text)
        language.select_by_value("dialect:renderman")
        wait_for(driver, "the error again", lambda d: "unexpected character `G`" in d.find_element(By.ID, "diagnostics").text)


def step_report_offline(driver, lpe_check):
    page = os.path.join(OUT, "report.html")
    fixtures = sorted(glob.glob("tests/testdata/usd/*.usda", root_dir=ROOT))
    subprocess.run([lpe_check, "report", *fixtures, "--html", page], check=True, cwd=ROOT, stdout=subprocess.DEVNULL)
    requests_made(driver)  # forget the explorer's requests
    driver.execute_cdp_cmd("Network.enable", {})
    driver.execute_cdp_cmd("Network.emulateNetworkConditions", {
        "offline": True, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1,
    })
    driver.get("file://" + page)
    wait_for(driver, "the report to draw", lambda d: d.find_element(By.TAG_NAME, "body").get_attribute("data-ready") == "true")
    files = driver.find_elements(By.CSS_SELECTOR, ".file")
    assert len(files) == len(fixtures), (len(files), len(fixtures))
    assert driver.find_elements(By.CSS_SELECTOR, '.graph svg [id^="s"]'), "no drawing in the report"
    shot(driver, "5-report")
    others = [u for u in requests_made(driver) if not u.startswith(("file://", "data:", "about:"))]
    assert others == [], others
    driver.execute_cdp_cmd("Network.emulateNetworkConditions", {
        "offline": False, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1,
    })


def main():
    lpe_check = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "target", "release", "lpe-check")
    os.makedirs(OUT, exist_ok=True)
    for old in glob.glob(os.path.join(OUT, "*.png")):
        os.remove(old)
    server, url = start_server(lpe_check)
    profile = tempfile.mkdtemp(prefix="lpe-explorer-chromium-")
    driver = browser(profile)
    steps = [
        ("an error shows its caret and message", lambda: step_error_caret(driver, url)),
        ("a list is drawn and partitioned", lambda: step_drawing_and_partition(driver)),
        ("a path's trace is highlighted", lambda: step_trace(driver)),
        ("two lines are compared", lambda: step_equivalence(driver)),
        ("a set too large to draw gives its size", lambda: step_too_large(driver)),
        ("the language selector reaches the API", lambda: step_language(driver)),
        ("the report opens offline, asking for nothing", lambda: step_report_offline(driver, lpe_check)),
    ]
    failed = 0
    try:
        for name, run in steps:
            started = time.monotonic()
            try:
                run()
                print("ok    %s (%.1f s)" % (name, time.monotonic() - started))
            except Exception:
                failed += 1
                print("FAIL  %s" % name)
                traceback.print_exc()
                shot(driver, "failed-" + name.split()[1])
    finally:
        driver.quit()
        server.terminate()
        server.wait()
        shutil.rmtree(profile, ignore_errors=True)
    print("explorer: %d passed, %d failed" % (len(steps) - failed, failed))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
