"""Objects made before importlib.reload(swingsim), as a notebook's autoreload does, are still
taken (issue 57: they were refused with "expected a swingsim.Participant, got
swingsim.Participant")."""
import importlib

import swingsim


def test_an_object_made_before_a_reload_is_still_taken(repo):
    before = swingsim.load_participant(repo / "participants" / "p1.yaml")
    old_class = type(before)
    reloaded = importlib.reload(swingsim)
    assert reloaded.Participant is not old_class  # the reload made a new class
    assert reloaded.simulate(before).swing_time_s == reloaded.simulate(repo / "participants" / "p1.yaml").swing_time_s


def test_an_object_of_another_class_of_the_same_name_is_refused(repo):
    class Participant:  # not swingsim's: its module is this test's
        pass
    try:
        swingsim.simulate(Participant())
    except TypeError as e:
        assert "expected a path or a swingsim.Participant" in str(e)
    else:
        raise AssertionError("accepted a foreign Participant")
