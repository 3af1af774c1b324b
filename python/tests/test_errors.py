"""Bad input raises ValueError with the command line's message, never a crash."""

import json

import numpy as np
import pytest

import vsr
from conftest import cli

GENOMES = np.zeros((2, 73), dtype=np.float32)


def cli_message(vsr_bin, *args):
    code, _, err = cli(vsr_bin, *args)
    assert code == 2 and err.startswith("vsr: "), err
    return err[len("vsr: "):].strip()


def test_a_disconnected_shape_says_what_the_command_line_says(vsr_bin):
    expected = cli_message(vsr_bin, "params", "--shape", "1001-1001", "--controller", "mlp")
    with pytest.raises(ValueError) as e:
        vsr.evaluate(GENOMES, "1001-1001", "attention", "flat")
    assert str(e.value) == expected and "separate pieces" in expected
    with pytest.raises(ValueError, match="separate pieces"):
        vsr.param_count("1001-1001", "mlp")


def test_an_unknown_controller_or_terrain(vsr_bin, tmp_path):
    expected = cli_message(vsr_bin, "params", "--shape", "biped-4x3", "--controller", "lstm")
    with pytest.raises(ValueError) as e:
        vsr.evaluate(GENOMES, "biped-4x3", "lstm", "flat")
    assert str(e.value) == expected
    path = tmp_path / "run.json"
    vsr.save_run(path, vsr.new_run(GENOMES[0], "biped-4x3", "attention"))
    expected = cli_message(vsr_bin, "evaluate", "--genome", str(path), "--terrain", "moon")
    with pytest.raises(ValueError) as e:
        vsr.evaluate(GENOMES, "biped-4x3", "attention", "moon")
    assert str(e.value) == expected and "unknown terrain" in expected


def test_a_wrong_genome_length_names_the_row_and_both_lengths():
    with pytest.raises(ValueError) as e:
        vsr.evaluate(np.zeros((3, 72)), "biped-4x3", "attention", "flat")
    assert str(e.value) == ("invalid input: genome 0 has 72 genes, but the attention "
                            "controller of a 10-voxel robot has 73")
    with pytest.raises(ValueError, match="the genome has 72 genes"):
        vsr.simulate(np.zeros(72), "biped-4x3", "attention", "flat")
    with pytest.raises(ValueError, match="must be a 2-D array, one genome per row"):
        vsr.evaluate(np.zeros((2, 1, 73)), "biped-4x3", "attention", "flat")


def test_nan_genes_are_refused_by_row_and_gene(vsr_bin, tmp_path):
    genomes = np.zeros((3, 73))
    genomes[2, 5] = np.nan
    with pytest.raises(ValueError) as e:
        vsr.evaluate(genomes, "biped-4x3", "attention", "flat")
    assert str(e.value) == "invalid input: gene 5 of genome 2 is NaN, genes must be finite numbers"
    with pytest.raises(ValueError, match="gene 5 of the genome is NaN"):
        vsr.simulate(genomes[2], "biped-4x3", "attention", "flat")
    # the command line meets NaN as a null gene of a run file; so does load_run
    run = json.loads(json.dumps(vsr.new_run(np.zeros(73), "biped-4x3", "attention"),
                                default=lambda a: a.tolist()))
    run["best"]["genome"][5] = None
    path = tmp_path / "nan.json"
    path.write_text(json.dumps(run))
    expected = cli_message(vsr_bin, "evaluate", "--genome", str(path), "--terrain", "flat")
    with pytest.raises(ValueError) as e:
        vsr.load_run(path)
    assert str(e.value) == expected and "gene 5 is null" in expected


def test_bad_arguments(vsr_bin, tmp_path):
    path = tmp_path / "run.json"
    vsr.save_run(path, vsr.new_run(GENOMES[0], "biped-4x3", "attention"))
    expected = cli_message(vsr_bin, "evaluate", "--genome", str(path), "--terrain", "flat",
                           "--seconds", "-1")
    with pytest.raises(ValueError) as e:
        vsr.evaluate(GENOMES, "biped-4x3", "attention", "flat", seconds=-1.0)
    assert str(e.value) == expected == "invalid input: episode seconds must be in (0, 3600], got -1"
    for threads in (0, -1, 2.5):
        with pytest.raises(ValueError, match=r"^invalid input: threads must be an integer of at "
                                             r"least 1, or None for every core; got "):
            vsr.evaluate(GENOMES, "biped-4x3", "attention", "flat", threads=threads)


@pytest.mark.parametrize("call", [
    lambda: vsr.evaluate(GENOMES, "biped-4x3", "attention", "flat", noise_seed=-1),
    lambda: vsr.evaluate_bodies(["biped-4x3"], GENOMES[:1], "attention", "flat", noise_seed=-1),
    lambda: vsr.simulate(GENOMES[0], "biped-4x3", "attention", "flat", noise_seed=-1),
    lambda: vsr.ablate(GENOMES[0], "biped-4x3", "attention", last_second=-1),
    lambda: vsr.new_run(GENOMES[0], "biped-4x3", "attention", evaluations=-1),
    lambda: vsr.codesign("scratch", 100, seed=-1),
])
def test_a_negative_count_or_seed_is_a_value_error_that_names_it(call):
    with pytest.raises(ValueError, match=r"^invalid input: \w+ must be an integer in "
                                         r"\[0, 2\^64 - 1\], got -1$"):
        call()


def test_a_gene_beyond_float32_is_refused_with_its_value():
    genomes = np.zeros((2, 73))
    genomes[1, 4] = -1e300
    message = ("is -1e+300, out of float32's range (genes are float32: at most 3.402823e+38 "
               "in magnitude)")
    with pytest.raises(ValueError) as e:
        vsr.evaluate(genomes, "biped-4x3", "attention", "flat")
    assert str(e.value) == f"invalid input: gene 4 of genome 1 {message}"
    for call in (lambda: vsr.simulate(genomes[1], "biped-4x3", "attention", "flat"),
                 lambda: vsr.new_run(genomes[1], "biped-4x3", "attention"),
                 lambda: vsr.Controller("biped-4x3", "attention", genomes[1])):
        with pytest.raises(ValueError) as e:
            call()
        assert str(e.value) == f"invalid input: gene 4 of the genome {message}"


def test_the_package_exports_only_its_api():
    assert not {"json", "np", "os"} & set(dir(vsr))
    assert all(hasattr(vsr, name) for name in vsr.__all__)


@pytest.mark.parametrize("call, named", [
    (lambda: vsr.evaluate(GENOMES, "biped-4x3", 3, "flat"), "controller"),
    (lambda: vsr.evaluate(GENOMES, None, "attention", "flat"), "shape"),
    (lambda: vsr.validate(GENOMES[0], "biped-4x3", "attention", set=1), "set"),
    (lambda: vsr.simulate(GENOMES[0], "biped-4x3", "attention", 0), "terrain"),
])
def test_a_word_that_is_not_a_string_is_named(call, named):
    with pytest.raises(TypeError, match=rf"^{named} must be a string such as "):
        call()


def test_a_run_file_given_as_a_genome_says_where_its_genes_are():
    with pytest.raises(TypeError, match=r"got a dict \(a run file\? its genes are run\['best'\]\['genome'\]\)"):
        vsr.validate({"best": {}}, "biped-4x3", "attention")


ANY = np.zeros(61, dtype=np.float32)


@pytest.mark.parametrize("call, named", [
    # integers: negative, beyond 2^64 - 1, fractional, a string, a bool
    (lambda: vsr.codesign("scratch", 100, 1, voxels=(-1, 5)), "voxels"),
    (lambda: vsr.codesign("scratch", 100, 1, voxels=(2, 2**64)), "voxels"),
    (lambda: vsr.codesign("scratch", 100, 1, grid=(3,)), "grid"),
    (lambda: vsr.codesign("scratch", 100, 1, grid=(2.5, 3)), "grid"),
    (lambda: vsr.codesign("scratch", 100, 1, grid="5x5"), "grid"),
    (lambda: vsr.codesign("scratch", -100, 1), "evals"),
    (lambda: vsr.codesign("scratch", 100.5, 1), "evals"),
    (lambda: vsr.codesign("scratch", "100", 1), "evals"),
    (lambda: vsr.codesign("scratch", 100, 2**64), "seed"),
    (lambda: vsr.codesign("scratch", 100, 1, batch=-2), "batch"),
    (lambda: vsr.codesign("scratch", 100, 1, threads=-1), "threads"),
    (lambda: vsr.evaluate(GENOMES, "biped-4x3", "attention", "flat", noise_seed=True), "noise_seed"),
    (lambda: vsr.evaluate(GENOMES, "biped-4x3", "attention", "flat", noise_seed=2**64), "noise_seed"),
    (lambda: vsr.evaluate(GENOMES, "biped-4x3", "attention", "flat", threads=True), "threads"),
    (lambda: vsr.evaluate_bodies(["11"], ANY, "attention-any", "flat", threads=2**70), "threads"),
    (lambda: vsr.ablate(GENOMES[0], "biped-4x3", "attention", last_second=2.5), "last_second"),
    (lambda: vsr.new_run(GENOMES[0], "biped-4x3", "attention", seed=1.5), "seed"),
    (lambda: vsr.Episode("biped-4x3", "flat", noise_seed=-3), "noise_seed"),
    (lambda: vsr.Episode("biped-4x3", "flat").reset(seed=2**65), "seed"),
    (lambda: vsr.validate(ANY, controller="attention-any", bodies=["11"], threads=0), "threads"),
    # numbers: a string, a bool, an int too large for a float, None where a number belongs
    (lambda: vsr.codesign("scratch", 100, 1, seconds="10"), "seconds"),
    (lambda: vsr.evaluate(GENOMES, "biped-4x3", "attention", "flat", seconds="10"), "seconds"),
    (lambda: vsr.evaluate(GENOMES, "biped-4x3", "attention", "flat", seconds=10**400), "seconds"),
    (lambda: vsr.evaluate(GENOMES, "biped-4x3", "attention", "flat", seconds=None), "seconds"),
    (lambda: vsr.evaluate_bodies(["11"], ANY, "attention-any", "flat", seconds=True), "seconds"),
    (lambda: vsr.simulate(GENOMES[0], "biped-4x3", "attention", "flat", seconds=[3]), "seconds"),
    (lambda: vsr.validate(GENOMES[0], "biped-4x3", "attention", seconds="30"), "seconds"),
    (lambda: vsr.validate(ANY, controller="attention-any", bodies=["11"], seconds="3"), "seconds"),
    (lambda: vsr.ablate(GENOMES[0], "biped-4x3", "attention", seconds=b"10"), "seconds"),
    (lambda: vsr.new_run(GENOMES[0], "biped-4x3", "attention", fitness="fast"), "fitness"),
    (lambda: vsr.new_run(GENOMES[0], "biped-4x3", "attention", seconds="30"), "seconds"),
    (lambda: vsr.Episode("biped-4x3", "flat", seconds="30"), "seconds"),
])
def test_a_bad_number_is_a_value_error_that_names_its_setting(call, named):
    with pytest.raises(ValueError, match=rf"^invalid input: {named} must be "):
        call()


@pytest.mark.parametrize("call", [
    lambda: vsr.codesign("scratch", 100, 1, seconds=-5),
    lambda: vsr.evaluate(GENOMES, "biped-4x3", "attention", "flat", seconds=float("nan")),
    lambda: vsr.new_run(GENOMES[0], "biped-4x3", "attention", seconds=1e9),
    lambda: vsr.Episode("biped-4x3", "flat", seconds=0),
])
def test_seconds_out_of_range_say_the_range(call):
    with pytest.raises(ValueError, match=r"^invalid input: episode seconds must be in \(0, 3600\]"):
        call()


def test_numpy_scalars_are_numbers():
    one = vsr.evaluate(GENOMES[0], "biped-4x3", "attention", "flat", seconds=np.float32(1.0),
                       noise_seed=np.uint64(3), threads=np.int64(1))
    assert one.tolist() == vsr.evaluate(GENOMES[0], "biped-4x3", "attention", "flat",
                                        seconds=1.0, noise_seed=3).tolist()
