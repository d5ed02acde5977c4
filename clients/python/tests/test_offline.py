"""The parts of the client that need no server: Retry-After and Link parsing, the retry bounds,
and a refused connection raised as ClearskyError (docs/clients.md)."""

from __future__ import annotations

import socket
import unittest
from datetime import datetime, timezone

from clearsky_client import ClearskyError, Client, RetryPolicy
from clearsky_client.data_results import next_cursor_of
from clearsky_client.retry import parse_retry_after


class RetryAfter(unittest.TestCase):
    def test_seconds_and_http_dates(self) -> None:
        self.assertEqual(parse_retry_after("5"), 5.0)
        now = datetime(2026, 11, 25, 12, 0, 0, tzinfo=timezone.utc)
        # RFC 9110 section 5.6.7: IMF-fixdate.
        self.assertEqual(parse_retry_after("Wed, 25 Nov 2026 12:00:07 GMT", now), 7.0)
        self.assertEqual(parse_retry_after("Wed, 25 Nov 2026 11:00:00 GMT", now), 0.0)
        self.assertIsNone(parse_retry_after(None))
        self.assertIsNone(parse_retry_after("soon"))
        self.assertIsNone(parse_retry_after("-1"))

    def test_bounds(self) -> None:
        policy = RetryPolicy(max_attempts=3, max_total_wait_s=10)
        self.assertEqual(policy.wait_before_retry(503, 4.0, 1, 0.0), 4.0)
        self.assertEqual(policy.wait_before_retry(429, 4.0, 2, 4.0), 4.0)
        self.assertIsNone(policy.wait_before_retry(503, 4.0, 3, 8.0))   # attempts spent
        self.assertIsNone(policy.wait_before_retry(503, 4.0, 2, 8.0))   # past the total wait
        self.assertIsNone(policy.wait_before_retry(503, None, 1, 0.0))  # no Retry-After
        self.assertIsNone(policy.wait_before_retry(500, 1.0, 1, 0.0))   # not a retried status
        with self.assertRaises(ValueError):
            RetryPolicy(max_attempts=0)


class LinkHeader(unittest.TestCase):
    def test_next_cursor(self) -> None:
        link = '</v1/evaluations?model=preetham&limit=100&cursor=693132>; rel="next"'
        self.assertEqual(next_cursor_of(link), "693132")
        self.assertIsNone(next_cursor_of(None))
        self.assertIsNone(next_cursor_of('</v1/jobs?cursor=a>; rel="prev"'))


class Connection(unittest.TestCase):
    def test_refused_connection_is_a_clearsky_error(self) -> None:
        with socket.socket() as unused:
            unused.bind(("127.0.0.1", 0))
            port = unused.getsockname()[1]
        with self.assertRaises(ClearskyError) as caught:
            Client(f"http://127.0.0.1:{port}", timeout=10).health()
        self.assertEqual((caught.exception.status, caught.exception.code),
                         (None, "connection_failed"))

    def test_base_url_is_checked(self) -> None:
        with self.assertRaises(ValueError):
            Client("127.0.0.1:8080")


if __name__ == "__main__":
    unittest.main()
