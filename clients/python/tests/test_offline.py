"""The parts of the client that need no server: Retry-After and Link parsing, the retry bounds,
and a refused connection raised as ClearskyError (docs/clients.md)."""

from __future__ import annotations

import socket
import unittest
from datetime import datetime, timezone

from clearsky_client import ClearskyError, Client, RetryPolicy
from clearsky_client.data_results import Evaluation, EvaluationSummary, next_cursor_of
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


class BroadbandEvaluationResults(unittest.TestCase):
    """A run on a broadband irradiance dataset as GET /v1/evaluations/{id}?samples=true and the
    list answer it (docs/data-api.md "Evaluations of broadband irradiance")."""

    COMPONENTS = [{"component": "ghi", "rmse_w_m2": 37.3, "mean_bias_w_m2": -34.2,
                   "samples_compared": 2, "errors_w_m2": [None, -30.1, -38.3]},
                  {"component": "dni", "rmse_w_m2": None, "mean_bias_w_m2": None,
                   "samples_compared": 0, "errors_w_m2": [None, None, None]}]

    def test_run_and_summary_read_the_components(self) -> None:
        run = Evaluation.from_json({
            "id": 4, "dataset": "roof", "model": "nishita93", "model_version": "1",
            "parameters": {}, "status": "succeeded", "rmse": 37.3, "rmse_unit": "W/m2",
            "samples_compared": 2, "captures": [], "irradiance_components": self.COMPONENTS})
        self.assertEqual(run.rmse_unit, "W/m2")
        self.assertEqual([c.component for c in run.irradiance_components], ["ghi", "dni"])
        self.assertEqual(run.irradiance_components[0].mean_bias_w_m2, -34.2)
        self.assertEqual(run.irradiance_components[0].errors_w_m2, [None, -30.1, -38.3])
        self.assertIsNone(run.irradiance_components[1].rmse_w_m2)
        summary = EvaluationSummary.from_json({
            "id": 4, "dataset": "roof", "model": "nishita93", "status": "succeeded", "rmse": 37.3,
            "rmse_unit": "W/m2", "samples_compared": 2, "job": None,
            "irradiance_components": [dict(c, errors_w_m2=None) for c in self.COMPONENTS]})
        self.assertEqual(summary.irradiance_components[0].rmse_w_m2, 37.3)
        self.assertEqual(summary.irradiance_components[1].samples_compared, 0)

    def test_a_run_on_captures_has_none(self) -> None:
        summary = EvaluationSummary.from_json({
            "id": 1, "dataset": "kider", "model": "preetham", "status": "succeeded",
            "rmse": 88.7, "rmse_unit": "mW/(m2.sr.nm)", "samples_compared": 81, "job": None,
            "irradiance_components": []})
        self.assertEqual(summary.rmse_unit, "mW/(m2.sr.nm)")
        self.assertEqual(summary.irradiance_components, [])


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
