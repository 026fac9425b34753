"""The Python reader and the player on damaged bags (issue 17, items 8 and 11).

The bags are ``tests/data/hostile/bags/*.bag`` (``make_bags.py`` there writes them): 60
messages, 30 on /cmd_vel and 30 on /chatter, 10 ms apart, each bag damaged in one way.
"""

from __future__ import annotations

import pytest

from workbench.bag import BagWarning, play, read_messages, summarize

#: bag -> (messages readable, text every warning of the read must contain)
EXPECTED = {
    "garbage_in_a_chunk.bag": (53, "byte 4974"),
    "chunk_start_2106.bag": (60, "the index is damaged"),
    "chunk_start_1970.bag": (60, "the index is damaged"),
    "record_length_past_the_end.bag": (58, "byte 4117"),
    "chunk_claims_4_gib.bag": (52, "more than the 256.0 MiB a chunk may hold"),
    "header_counts_4e9_connections.bag": (60, "fewer connections than the header says"),
    "cut_in_half.bag": (18, "byte"),
    "bz2_chunk_damaged.bag": (52, "bz2 data does not decompress"),
    "lz4_chunk_damaged.bag": (52, "lz4 data does not decompress"),
    "message_does_not_decode.bag": (59, "does not decode as std_msgs/String"),
    "unknown_type_bad_definition.bag": (30, "does not decode as xx_msgs/Strange"),
}


@pytest.fixture(scope="module")
def bags(data_dir):
    return data_dir / "hostile" / "bags"


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_everything_readable_is_returned_in_order_with_a_warning(bags, name):
    count, text = EXPECTED[name]
    with pytest.warns(BagWarning) as caught:
        messages = list(read_messages(bags / name))
    assert len(messages) == count
    stamps = [m.stamp_ns for m in messages]
    assert stamps == sorted(stamps)
    assert any(text in str(w.message) for w in caught), [str(w.message) for w in caught]
    for message in messages:  # what is returned is what was recorded
        if message.topic == "/chatter" and message.typename == "std_msgs/String":
            index = int(message.msg.data.split()[1])
            assert message.stamp_ns == round((1638598185.0 + 0.01 * index + 0.005) * 1e9)


def test_raw_reading_skips_only_the_damaged_chunks(bags):
    with pytest.warns(BagWarning, match="skipped the damaged chunk at byte 5833"):
        raw = list(read_messages(bags / "chunk_claims_4_gib.bag", raw=True))
    assert len(raw) == 52 and all(isinstance(m.msg, bytes) for m in raw)


@pytest.mark.parametrize("name", ["chunk_start_2106.bag", "chunk_start_1970.bag"])
def test_a_damaged_chunk_time_does_not_make_play_wait(bags, name):
    clock = {"t": 0.0}
    published = []

    def sleep(seconds):
        clock["t"] += seconds

    with pytest.warns(BagWarning):
        report = play(
            bags / name,
            lambda topic, typename, msg: published.append(topic),
            delay=0.0,
            sleep=sleep,
            now=lambda: clock["t"],
        )
    assert report.published == 60 == len(published)
    assert clock["t"] == pytest.approx(0.295, abs=0.01)  # the messages' own span, no more


def test_summary_counts_what_the_index_can_vouch_for(bags):
    summary = summarize(bags / "record_length_past_the_end.bag")
    assert summary.indexed and summary.message_count == 58
    assert summary.warnings == [
        "skipped the damaged chunk at byte 4117 (record header of 2147483632 bytes does not "
        "fit; 2 messages lost)"
    ]
    walked = summarize(bags / "chunk_start_2106.bag")
    assert not walked.indexed and walked.message_count == 60
    assert walked.start_ns == round(1638598185.0 * 1e9)
