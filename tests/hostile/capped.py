"""What the hostile-input drivers share: running a program under an
address-space cap (RLIMIT_AS, as `ulimit -v`) and the CLI's failure rule."""
import resource


def address_space_cap(megabytes):
    """A preexec_fn capping the child's address space (None: no cap)."""
    if not megabytes:
        return None
    limit = megabytes << 20

    def cap():
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    return cap


def one_error_line_last(stderr):
    """Whether stderr holds exactly one `gab: error:` line, and it comes last."""
    lines = [line for line in stderr.splitlines() if line]
    errors = [line for line in lines if line.startswith("gab: error: ")]
    return len(errors) == 1 and lines[-1] == errors[0]
