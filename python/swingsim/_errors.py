"""The package's errors and its warning (part of the swingsim package: swingsim/__init__.py
re-exports them as swingsim.InputError, swingsim.RunError and swingsim.SwingsimWarning), and
the wording of a bad argument the other parts use."""
from swingsim._swingsim import InputError, RunError

InputError.__doc__ = ("Bad input (a ValueError): a file, an edited field or an argument the command line would refuse; "
                      "the message is the command line's `file:line: key: what was expected (got VALUE)`.")
RunError.__doc__ = ("A run that failed (a RuntimeError): a swing that cannot be simulated, as the command line "
                    "reports it.")


class SwingsimWarning(UserWarning):
    """A warning about the data a swingsim call read (a flipped sign, a column read without
    the pelvis tilt, a force file left to the kinematics, ...): the same text the command
    line prints on stderr and the JSON keeps under "warnings"."""


def _argument_problem(where, expected, value):
    shown = repr(value)
    return f"{where}: {expected}, got {type(value).__name__} {shown[:80]}"
