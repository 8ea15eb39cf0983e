"""Issue 38 §4: wrong Python types are TypeErrors and bad values
ValueErrors, each naming the argument (never pybind11's "Unable to cast
Python instance to C++ type"); numbers in messages are short; a play area's
NaN is named."""
import pytest

import impossible

CAST = "Unable to cast"


def raised(call):
    with pytest.raises(Exception) as info:
        call()
    assert CAST not in str(info.value), str(info.value)
    return info


@pytest.fixture(scope="module")
def layout():
    return impossible.builtin()


@pytest.mark.parametrize("size, error, words", [
    ("abc", TypeError, "size: expected (width, height), two integers, got str"),
    ((3,), ValueError, "size: expected (width, height), two integers, got 1 items"),
    ((1e10, 1), TypeError, "size: width: expected an integer, got float"),
    ((8, "9"), TypeError, "size: height: expected an integer, got str"),
    ((10**30, 8), ValueError, "size: width: 1000000000000000000000000000000 is too large"),
])
def test_sizes(layout, size, error, words):
    info = raised(lambda: impossible.trace(layout, size=size))
    assert info.type is error and words in str(info.value)
    info = raised(lambda: impossible.Renderer(layout, size=size))
    assert info.type is error and words in str(info.value)


def test_scalars_name_their_argument(layout):
    cases = [
        (lambda: impossible.trace(layout, size=(8, 8), room=5), TypeError, "room: expected a room id (str), got int"),
        (lambda: impossible.trace(layout, size=(8, 8), light_depth=2.5), TypeError,
         "light_depth: expected an integer, got float"),
        (lambda: impossible.trace(layout, size=(8, 8), ipd="a"), TypeError, "ipd: expected a number, got str"),
        (lambda: impossible.trace(layout, size=(8, 8), fov=[1]), TypeError, "fov: expected a number, got list"),
        (lambda: impossible.generate("4x4", 2, 1), TypeError,
         "play_area: expected (width, depth) or a polygon [(x, z), ...], got str"),
        (lambda: impossible.generate((4, "x"), 2, 1), TypeError, "play_area: depth: expected a number, got str"),
        (lambda: impossible.generate([(0, 0), (4, 0, 1), (4, 4)], 2, 1), ValueError,
         "play_area: expected corners of 2 numbers (x, z)"),
    ]
    for call, error, words in cases:
        info = raised(call)
        assert info.type is error and words in str(info.value), str(info.value)
    # Still what the library says of a value in range of the type.
    with pytest.raises(ValueError, match="light_depth: 100000000000000000000 is too large"):
        impossible.trace(layout, size=(8, 8), light_depth=10**20)
    with pytest.raises(impossible.Error, match="light_depth 20 is not in 0..16"):
        impossible.trace(layout, size=(8, 8), light_depth=20)


def test_numbers_in_messages_are_short(layout):
    info = raised(lambda: impossible.trace(layout, size=(8, 8), pose=(0, 1.6, 0, 0, 0, 1e300)))
    assert str(info.value) == "pose: 1e+300 is not a finite number within ±10000000"


def test_a_play_areas_nan_is_named():
    nan = float("nan")
    with pytest.raises(impossible.Error, match=r"corner 2 \(nan, 4\) is not a coordinate within \+-100000 m"):
        impossible.generate([(0, 0), (4, 0), (nan, 4)], 2, 1)
    with pytest.raises(impossible.Error, match=r"each side of the play area must be 1..1000 m \(got nan by 4\)"):
        impossible.generate((nan, 4), 2, 1)
    # A layout's: Python's json writes NaN, which JSON has not.
    text = ('{"play_area": {"polygon": [[0, 0], [4, 0], [NaN, 4]]}, '
            '"rooms": [{"id": "a", "min": [0, 0, 0], "max": [3, 3, 3]}]}')
    with pytest.raises(impossible.Error, match=r"<string>:1:45: invalid JSON: .*\(NaN: JSON has no NaN or infinity"):
        impossible.parse(text)
