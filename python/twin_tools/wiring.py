"""The twin's wiring as the Python tools read it: the same one definition the C++ nodes read
(src/cosim/wiring.hpp).

- The participants and the scenarios they run in: one include of launch/include/participant.launch
  each, in launch/include/urban.launch (its `if` = its scenarios).
- What each publishes: src/<name>/node/topics.yaml (`publishes: {key: package/MessageType}`); the
  topic of key k is /<name>/<k>.

A tool names a topic by participant and key (topic("engine", "state")): a key its participant does
not declare is a WiringError naming the topics.yaml and the key, when the tool starts."""
import functools
import os
import xml.etree.ElementTree as ET

import yaml

from twin_tools.paths import REPO

URBAN_LAUNCH = os.path.join(REPO, "launch", "include", "urban.launch")


class WiringError(ValueError):
    pass


@functools.lru_cache(maxsize=None)
def participants():
    """The participants of the shipped scenarios (their launch includes), in launch order."""
    names = []
    for inc in ET.parse(URBAN_LAUNCH).getroot().iter("include"):
        if inc.get("file", "").endswith("/participant.launch"):
            names += [a.get("value") for a in inc.findall("arg") if a.get("name") == "name"]
    if not names:
        raise WiringError("%s: no include of participant.launch" % URBAN_LAUNCH)
    return tuple(names)


def topics_file(participant):
    return os.path.join(REPO, "src", participant, "node", "topics.yaml")


@functools.lru_cache(maxsize=None)
def declared(participant):
    """{key: message type} that `participant` publishes (its topics.yaml)."""
    path = topics_file(participant)
    try:
        with open(path) as f:
            doc = yaml.safe_load(f) or {}
    except OSError as e:
        raise WiringError("%s: cannot read the topics of participant '%s' (%s)" % (path, participant, e.strerror))
    pub = doc.get("publishes")
    if not isinstance(pub, dict) or not all(isinstance(v, str) for v in pub.values()):
        raise WiringError("%s: key 'publishes': expected a map key -> message type" % path)
    return dict(pub)


def topic(participant, key):
    """The topic `participant` publishes under `key`: "/<participant>/<key>"."""
    if key not in declared(participant):
        raise WiringError("%s: key 'publishes/%s': not declared (it declares %s)"
                          % (topics_file(participant), key, ", ".join(sorted(declared(participant)))))
    return "/%s/%s" % (participant, key)


def message_type(participant, key):
    topic(participant, key)
    return declared(participant)[key]


def message_class(participant, key):
    """The Python message class of a declared topic (needs the built messages on PYTHONPATH)."""
    import roslib.message
    name = message_type(participant, key)
    cls = roslib.message.get_message_class(name)
    if cls is None:
        raise WiringError("%s: key 'publishes/%s': message type %s not found (is the package built and its "
                          "devel space sourced?)" % (topics_file(participant), key, name))
    return cls
