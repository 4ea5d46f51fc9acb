"""docs/integrating-a-game.md's commands run as written (issue #62): every fenced block marked
`sh test` is run with bash, in order, in a fresh folder that looks like the repository's root
(build/, games/ and tests/ linked in, the build's psxrl on PATH); each must exit 0 and print every
text its `# prints: TEXT` comments name."""
import os
import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
GUIDE = ROOT / "docs" / "integrating-a-game.md"


def guide_blocks():
    return re.findall(r"^```sh test\n(.*?)^```$", GUIDE.read_text(), flags=re.S | re.M)


def test_the_guide_has_blocks_to_run():
    assert len(guide_blocks()) >= 5


def test_guide_commands_run_as_written(tmp_path):
    build = Path(os.environ.get("PSXRL_BUILD_DIR", ROOT / "build"))
    for name, target in (("build", build), ("games", ROOT / "games"), ("tests", ROOT / "tests")):
        (tmp_path / name).symlink_to(target)
    env = dict(os.environ, PATH=f"{build}{os.pathsep}{os.environ['PATH']}")
    env.pop("PSXRL_GAMES", None)
    for block in guide_blocks():
        done = subprocess.run(["bash", "-euo", "pipefail", "-c", block], cwd=tmp_path, env=env, capture_output=True,
                              text=True, timeout=600)
        assert done.returncode == 0, f"{block}\nexit {done.returncode}\n{done.stdout}\n{done.stderr}"
        for expected in re.findall(r"^# prints: (.*)$", block, flags=re.M):
            assert expected in done.stdout, f"{block}\ndid not print {expected!r}:\n{done.stdout}"
