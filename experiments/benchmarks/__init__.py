"""The benchmarks behind ``soccer-sim bench``: one module per benchmark, and the options the match benchmarks share."""


def add_match_arguments(parser, matches: int) -> None:
    """The options every match benchmark takes: --home, --away, --matches, --cycles, --seed."""
    from experiments.limits import ranged

    parser.add_argument("--home", default="chaser", help="home team (default: chaser)")
    parser.add_argument("--away", default="chaser", help="away team (default: chaser)")
    parser.add_argument("--matches", type=ranged("matches"), default=matches, help=f"matches to play (default: {matches})")
    parser.add_argument("--cycles", type=ranged("cycles"), default=None, help="cycles per match (default: a full match)")
    parser.add_argument("--seed", type=ranged("seed"), default=0, help="seed of the first match; match i uses seed + i")
