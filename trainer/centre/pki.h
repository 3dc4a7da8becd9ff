#pragma once
// The centre's PKI for DDS Security (docs/training-centre.md, "Security"), made with
// OpenSSL's libcrypto (no openssl program needed):
//
//   DIR/identity_ca.pem, identity_ca.key        the identity CA (self-signed, EC P-256)
//   DIR/permissions_ca.pem, permissions_ca.key  the permissions CA (self-signed, EC P-256)
//   DIR/governance.xml, governance.p7s          the governance document, S/MIME signed
//   DIR/nodes/NAME/identity.pem, identity.key   a node's identity (CN=NAME, by the identity CA)
//   DIR/nodes/NAME/permissions.xml, .p7s        its permissions, S/MIME signed
//
// Private keys are mode 0600. Nothing existing is ever replaced. A node's folder is all a
// node needs besides the three public files identity_ca.pem, permissions_ca.pem and
// governance.p7s; the CA keys stay on the computer that issues identities.

#include <QString>
#include <QStringList>

namespace trainer::centre::pki {

/// The files a node of the centre uses, for the bus.
struct NodeFiles {
    QString identityCa, permissionsCa, governance;  // shared by the centre
    QString certificate, privateKey, permissions;   // the node's own
    QStringList all() const { return {identityCa, permissionsCa, governance, certificate, privateKey, permissions}; }
};
NodeFiles nodeFiles(const QString& dir, const QString& node);

/// Makes the centre's CAs and its governance document in `dir` (created if missing).
/// False with a translated `error` when they exist already or a file cannot be written.
bool createCentre(const QString& dir, QString* error);

/// Issues the identity and the permissions of node `name` (valid 10 years) in dir/nodes/NAME.
bool issueNode(const QString& dir, const QString& name, QString* error);

/// Checks a node's files before DDS sees them: all present, the certificate issued by the
/// identity CA and in its validity, the key its own. False with a translated `error` that
/// says which file and what to do.
bool checkNode(const QString& dir, const QString& name, QString* error);

/// A node name fit for a certificate's CN and a folder name (letters, digits, - _ . @).
bool validNodeName(const QString& name);

}  // namespace trainer::centre::pki
