"""One version everywhere: CMakeLists.txt's project version is the library's (core/version.hpp),
which the CLI's --version and Python's emit.__version__ report."""

import re
import subprocess

import emit
from conftest import SOURCE_DIR


def test_the_cli_and_the_module_report_the_projects_version(cli):
    project = re.search(r"project\(emit VERSION (\d+\.\d+\.\d+)", (SOURCE_DIR / "CMakeLists.txt").read_text())
    assert project, "CMakeLists.txt names no project version"
    assert emit.__version__ == project.group(1)
    printed = subprocess.run([cli, "--version"], check=True, capture_output=True, text=True).stdout
    assert printed.strip() == f"emit {project.group(1)}"
