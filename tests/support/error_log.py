"""Collecting what the simulator logs at ERROR or above while a test runs (a handler's traceback, a
reply that does not encode), for tests that must see none."""

import logging


class ErrorLog(logging.Handler):
    def __init__(self):
        super().__init__(logging.ERROR)
        self.records = []

    def emit(self, record):
        self.records.append(record)
