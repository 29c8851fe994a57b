"""Results (swingsim/_results.py): what a result prints."""
from swingsim import Result


def test_a_result_of_nested_parts_prints_their_sizes():
    # Once printed as an empty "Result()" when every value was nested.
    nested = Result({"participants": [{"name": "P1"}, {"name": "P2"}], "settings": {"a": 1, "b": 2}})
    assert repr(nested) == "Result(participants=[2 items], settings={2 keys})"
    mixed = Result({"study": "burkett", "swing_time_s": 0.429, "rows": []})
    assert repr(mixed) == "Result(study='burkett', swing_time_s=0.429, rows=[0 items])"
    # The nested parts are Results themselves.
    assert repr(nested.participants[0]) == "Result(name='P1')"
