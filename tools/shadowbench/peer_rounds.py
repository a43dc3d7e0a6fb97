"""Our times against the OpenSceneGraph peer's when both run in turn (tools/results.sh steps 11 and 14): the
machine's speed drifts by up to 2x within a minute, so a scene runs rounds of ours with the peer's run before the
first and after each, and each round is compared with the peer's runs either side of it."""
import statistics


def bracketed(peers, key, rounds):
    """Per round, the mean of the peer's `key` time (a run's "shadowedMs" or "unshadowedMs" median) in its runs
    either side of it: `peers` holds the run before the first round and one after each."""
    if len(peers) != rounds + 1:
        raise ValueError(f"{rounds} rounds need {rounds + 1} peer runs around them, not {len(peers)}")
    return [statistics.mean(run[key]["median"] for run in peers[n:n + 2]) for n in range(rounds)]


def median_ratio(ours, theirs):
    """The median over rounds of our time over the peer's in the same round."""
    if len(ours) != len(theirs) or not ours:
        raise ValueError(f"{len(ours)} of our rounds against {len(theirs)} of the peer's")
    return statistics.median(a / b for a, b in zip(ours, theirs))
