"""Helpers shared by the tests: scenes, an in-process simulator, a protocol client, C builds."""
