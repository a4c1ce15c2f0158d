"""The errors of rodyn_post and the exit statuses of its commands, in one place.

Exception types (each message names the file, and the line or column when known):
  RodynResultsError  a results file is missing or malformed (the readers)
  InputError         a request the results cannot answer: a time outside the run, an
                     arc length off the line, an unknown line, ... (the commands)
  ReferenceError     a malformed reference CSV (compare); an InputError
  UnitError          a unit that is not in rodyn_post.units.UNITS; a ValueError
  WriteError         an output folder or file cannot be written

Exit statuses of every command (rodyn_post.cli.run maps the exceptions to them):
  0 success, 1 bad input (RodynResultsError, InputError), 2 bad command line
  (argparse), 3 an output cannot be written (WriteError); rodyn-compare adds 4: a
  metric above its --tol.
"""

EXIT_OK = 0
EXIT_BAD_INPUT = 1
EXIT_USAGE = 2
EXIT_WRITE = 3
EXIT_TOLERANCE = 4


class RodynResultsError(Exception):
    """A results file is missing or malformed; the message names the file."""


class InputError(Exception):
    """A request that these results cannot answer (a time outside the run, an arc
    length off the line, an unknown line, ...): bad input, exit status 1."""


class ReferenceError(InputError):  # noqa: A001  (the name compare's users know)
    """A malformed reference CSV; the message names the file (and the line)."""


class UnitError(ValueError):
    """A unit that is not in UNITS."""


class WriteError(Exception):
    """An output folder or file cannot be written: exit status 3."""


# exception type -> exit status, most specific first (cli.run uses the first match)
EXIT_STATUS = ((RodynResultsError, EXIT_BAD_INPUT), (InputError, EXIT_BAD_INPUT),
               (WriteError, EXIT_WRITE))


def exit_status(exc: BaseException):
    """The exit status of a known failure, None for an unexpected exception."""
    for kind, status in EXIT_STATUS:
        if isinstance(exc, kind):
            return status
    return None
