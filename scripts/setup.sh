#!/usr/bin/env bash
# Installs every dependency psxrl needs (Debian packages, then PyPI packages), configures and
# builds the project into build/. Safe to run again: installed packages are skipped.
set -euo pipefail
cd "$(dirname "$0")/.."

APT_PACKAGES=(
  cmake ninja-build g++ pkg-config ccache
  libgtest-dev libpng-dev libsdl2-dev libosmesa6-dev libeigen3-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev xvfb xauth xdotool
  libtorch-dev pybind11-dev liblua5.4-dev lua5.4 zlib1g-dev libtomlplusplus-dev libcli11-dev libxbyak-dev
  gcc-mipsel-linux-gnu binutils-mipsel-linux-gnu
  xfonts-shinonome pcf2bdf  # the HLE kernel's kanji font (src/core/bios/hle_font.h) and its test
  # clang's sanitizer and libFuzzer runtimes (scripts/fuzz.sh) are only recommended by clang-16,
  # and recommendations are not installed.
  clang-16 libfuzzer-16-dev libclang-rt-16-dev
  python3 python3-dev python3-pip python3-venv
  python3-torch python3-pandas python3-matplotlib python3-cloudpickle
)
PIP_PACKAGES=(numpy gymnasium pytest scikit-build-core)

missing=()
for p in "${APT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  echo "setup: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

PY=${PYTHON:-python3}
pip_missing=()
for p in "${PIP_PACKAGES[@]}"; do
  "$PY" -c "import ${p//-/_}" 2>/dev/null || pip_missing+=("$p")  # import names use _ for -
done
if [ ${#pip_missing[@]} -gt 0 ]; then
  echo "setup: pip installing ${pip_missing[*]}"
  "$PY" -m pip install -q "${pip_missing[@]}" || "$PY" -m pip install -q --break-system-packages "${pip_missing[@]}"
fi

# Stable-Baselines3 (examples/sb3_train.py, the python_sb3_smoke test) needs PyTorch. Debian's
# CPU-only python3-torch (the same 1.13 as libtorch-dev) belongs to Debian's /usr/bin/python3, so
# SB3 lives in .venv-sb3, a virtual environment of that interpreter seeing its Debian packages;
# SB3 2.4 is the last release that accepts torch 1.13 (2.5 needs torch 2.3). psxrl.make_vec needs
# Gymnasium 1.1 (gymnasium.vector.AutoresetMode); SB3 2.4.1 declares gymnasium<1.1 but runs on
# 1.1.1 (python_sb3_smoke checks it, make_vec included), hence --no-deps. An older .venv-sb3 with
# Gymnasium 1.0 is upgraded in place.
if [ ! -x .venv-sb3/bin/python ] ||
   ! .venv-sb3/bin/python -c "import stable_baselines3, torch; from gymnasium.vector import AutoresetMode" 2>/dev/null; then
  echo "setup: making .venv-sb3 (Stable-Baselines3 over Debian's python3-torch)"
  /usr/bin/python3 -m venv --system-site-packages .venv-sb3
  .venv-sb3/bin/python -m pip install -q --no-deps "stable-baselines3==2.4.1" "gymnasium==1.1.1" farama-notifications
fi
# Minari (psxrl.offline, docs/offline.md; ctest python_offline_tests) joins SB3 in .venv-sb3, over
# Debian's NumPy 1.24: Minari 0.5.4 needs NumPy 2, which torch 1.13 is not built for, and 0.5.1
# runs on 1.24 with h5py 3.12 (checked 2026-12-07). pytest runs python_offline_tests.
if ! .venv-sb3/bin/python -c "import minari, h5py, pytest" 2>/dev/null; then
  echo "setup: pip installing Minari into .venv-sb3"
  .venv-sb3/bin/python -m pip install -q --no-deps "minari==0.5.1"
  .venv-sb3/bin/python -m pip install -q "h5py>=3.8,<3.13" "typer>=0.9" pytest
fi

# Ray and RLlib (psxrl.ray, docs/scaling.md; ctest python_ray_tests) also need PyTorch, so they
# too live over Debian's python3-torch, in .venv-ray of their own: RLlib pins a newer Gymnasium
# than SB3 2.4 accepts. NumPy stays Debian's 1.24, which torch 1.13 is built against, so pyarrow
# (imported by Ray Tune, which RLlib uses) is held below 20: 19 works with NumPy 1.24, the newest
# needs NumPy 2. psutil: the tests check which addresses the cluster listens on.
RAY_VERSION=2.60.0
if [ ! -x .venv-ray/bin/python ] || ! .venv-ray/bin/python -c \
     "import ray, pyarrow, psutil, pytest, torch; assert ray.__version__ == '$RAY_VERSION'" 2>/dev/null; then
  echo "setup: making .venv-ray (Ray $RAY_VERSION with RLlib over Debian's python3-torch)"
  /usr/bin/python3 -m venv --system-site-packages .venv-ray
  .venv-ray/bin/python -m pip install -q "ray[rllib]==$RAY_VERSION" "pyarrow<20" "numpy<2" psutil pytest
fi

# ccache lets `pip install .` below reuse what this build compiles: the module's build tree
# compiles the same core and bindings with the same flags, which would otherwise take minutes.
# CMake takes the launcher from these variables when it first configures a build tree, and
# scikit-build-core's compiler is g++, so this one uses g++ too (ccache keys on the name).
export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR=$PWD
export CC=${CC:-gcc} CXX=${CXX:-g++}
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build
# The Python module for `import psxrl` (pyproject.toml: scikit-build-core drives this CMake project
# in build-pip/, building only the module and Tumble's program). No build isolation: its build
# requirements are the packages installed above, so no download is needed.
echo "setup: pip installing the psxrl Python module"
"$PY" -m pip install -q --no-build-isolation . || "$PY" -m pip install -q --no-build-isolation --break-system-packages .
