"""The parts of the eye modules written by hand: per RoBIOS group, the functions that convert values,
check buffers or keep state in Python. The generated module of the group (eye/<group>.py) re-exports
them; interface/protocol.json marks them "python": "hand"."""
