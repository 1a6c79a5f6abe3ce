# SPDX-License-Identifier: MIT
"""The equation-of-state example: its reference, its argument checks, and a
plot that degrades to a message when neither matplotlib nor gnuplot is
there.  (make test-python runs the example itself.)"""
import builtins
import importlib.util
import os

import pytest

from conftest import PYTHON_DIR

spec = importlib.util.spec_from_file_location("hard_disk_eos", os.path.join(PYTHON_DIR, "examples", "hard_disk_eos.py"))
eos = importlib.util.module_from_spec(spec)
spec.loader.exec_module(eos)


def test_henderson_reference_values():
    # Z = (1 + eta^2/8) / (1 - eta)^2: 1 at zero density, second virial
    # coefficient 2 (in eta), and two values worked by hand.
    assert eos.henderson(0.0) == 1.0
    assert (eos.henderson(1e-6) - 1) / 1e-6 == pytest.approx(2.0, rel=1e-5)
    assert eos.henderson(0.4) == pytest.approx(1.02 / 0.36)
    assert eos.henderson(0.5) == pytest.approx(4.125)


@pytest.mark.parametrize("argv", [["--eta", "0.7"], ["--eta", "x"], ["--side", "3"], ["--impacts", "-1"],
                                  ["--bogus"]])
def test_bad_arguments_exit_2(argv, capsys):
    with pytest.raises(SystemExit) as e:
        eos.main(argv)
    assert e.value.code == 2
    assert "error" in capsys.readouterr().err


def test_small_run_agrees(capsys):
    assert eos.main(["--eta", "0.3", "--side", "8", "--impacts", "40"]) == 0
    assert "passed" in capsys.readouterr().out


def test_plot_without_matplotlib_or_gnuplot(monkeypatch, tmp_path):
    real_import = builtins.__import__

    def no_matplotlib(name, *args, **kwargs):
        if name.startswith("matplotlib"):
            raise ImportError(name)
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_matplotlib)
    monkeypatch.setattr(eos.shutil, "which", lambda _: None)
    path = tmp_path / "z.png"
    assert eos.plot(str(path), [(0.3, 2.05, 0.01, 2.06)]) is None
    assert not path.exists()
