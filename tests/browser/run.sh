#!/usr/bin/env bash
# The explorer page in a real browser, in one command (tests/browser/README.md): installs
# Debian's chromium and chromium-driver when they are missing (as root; else says how),
# Selenium in target/browser-venv (pinned in .ci/browser-requirements.txt), builds
# lpe-check and runs tests/browser/explorer.py. Screenshots go to target/explorer/.
set -euo pipefail
cd "$(dirname "$0")/../.."
if ! command -v chromium > /dev/null || ! command -v chromedriver > /dev/null; then
    if [ "$(id -u)" != 0 ]; then
        echo "error: chromium and chromedriver are missing: sudo apt-get install chromium chromium-driver" >&2
        exit 1
    fi
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium chromium-driver > /dev/null
fi
python3 -m venv target/browser-venv
if ! target/browser-venv/bin/pip install --quiet -r .ci/browser-requirements.txt; then
    echo "error: installing selenium failed: the page cannot be tested in a browser" >&2
    exit 1
fi
cargo build --release -q -p lpe-cli
target/browser-venv/bin/python tests/browser/explorer.py target/release/lpe-check
