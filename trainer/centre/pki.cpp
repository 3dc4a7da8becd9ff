#include "trainer/centre/pki.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>

#include <openssl/bio.h>
#include <openssl/bn.h>
#include <openssl/evp.h>
#include <openssl/pem.h>
#include <openssl/pkcs7.h>
#include <openssl/x509.h>
#include <openssl/x509v3.h>

#include <memory>
#include <string>

namespace trainer::centre::pki {

namespace {


template <typename T, void (*F)(T*)>
struct Free {
    void operator()(T* p) const { F(p); }
};
using Key = std::unique_ptr<EVP_PKEY, Free<EVP_PKEY, EVP_PKEY_free>>;
using Cert = std::unique_ptr<X509, Free<X509, X509_free>>;
using Bio = std::unique_ptr<BIO, Free<BIO, BIO_free_all>>;
using P7 = std::unique_ptr<PKCS7, Free<PKCS7, PKCS7_free>>;

constexpr int kYears = 10;

QString path(const QString& dir, const char* file) { return QDir(dir).filePath(QString::fromLatin1(file)); }

QByteArray bioBytes(BIO* b)
{
    char* data = nullptr;
    const long n = BIO_get_mem_data(b, &data);
    return QByteArray(data, static_cast<qsizetype>(n));
}

/// Writes a new file (never replacing one); `secret` files are made mode 0600 from the start.
bool writeNew(const QString& file, const QByteArray& bytes, bool secret, QString* error)
{
    QFile f(file);
    if (f.exists()) {
        if (error) *error = QCoreApplication::translate("CentrePki", "%1 exists already: a PKI file is never replaced (remove it first if you mean to).").arg(file);
        return false;
    }
    const QFileDevice::Permissions mode = secret ? (QFileDevice::ReadOwner | QFileDevice::WriteOwner)
                                                 : (QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ReadGroup |
                                                    QFileDevice::ReadOther);
    if (!f.open(QIODevice::WriteOnly | QIODevice::NewOnly, mode) || f.write(bytes) != bytes.size() || !f.flush()) {
        if (error) *error = QCoreApplication::translate("CentrePki", "Could not write %1: %2.").arg(file, f.errorString());
        return false;
    }
    f.close();
    f.setPermissions(mode);  // whatever the umask did
    return true;
}

Key newKey() { return Key(EVP_EC_gen("P-256")); }

bool addExt(X509* cert, X509* issuer, int nid, const char* value)
{
    X509V3_CTX ctx;
    X509V3_set_ctx_nodb(&ctx);
    X509V3_set_ctx(&ctx, issuer, cert, nullptr, nullptr, 0);
    X509_EXTENSION* ext = X509V3_EXT_conf_nid(nullptr, &ctx, nid, value);
    if (!ext) return false;
    const bool ok = X509_add_ext(cert, ext, -1) == 1;
    X509_EXTENSION_free(ext);
    return ok;
}

/// A certificate for `key` named CN=`cn`, signed by `issuerKey` (self-signed when `issuer` is null).
Cert makeCert(EVP_PKEY* key, const QString& cn, bool ca, X509* issuer, EVP_PKEY* issuerKey)
{
    Cert x(X509_new());
    if (!x || X509_set_version(x.get(), 2) != 1) return {};
    BIGNUM* serial = BN_new();
    BN_rand(serial, 63, BN_RAND_TOP_ANY, BN_RAND_BOTTOM_ANY);
    BN_to_ASN1_INTEGER(serial, X509_get_serialNumber(x.get()));
    BN_free(serial);
    X509_gmtime_adj(X509_getm_notBefore(x.get()), -3600);
    X509_time_adj_ex(X509_getm_notAfter(x.get()), 365 * kYears + kYears / 4, 0, nullptr);
    X509_set_pubkey(x.get(), key);
    X509_NAME* name = X509_get_subject_name(x.get());
    const QByteArray cnUtf8 = cn.toUtf8();
    X509_NAME_add_entry_by_txt(name, "CN", MBSTRING_UTF8, reinterpret_cast<const unsigned char*>(cnUtf8.constData()), -1, -1, 0);
    X509_set_issuer_name(x.get(), issuer ? X509_get_subject_name(issuer) : name);
    X509* signer = issuer ? issuer : x.get();
    const bool ok = addExt(x.get(), signer, NID_basic_constraints, ca ? "critical,CA:TRUE" : "critical,CA:FALSE") &&
                    addExt(x.get(), signer, NID_key_usage,
                           ca ? "critical,digitalSignature,keyCertSign,cRLSign" : "critical,digitalSignature,keyAgreement") &&
                    addExt(x.get(), signer, NID_subject_key_identifier, "hash") &&
                    (issuer == nullptr || addExt(x.get(), signer, NID_authority_key_identifier, "keyid:always"));
    if (!ok || X509_sign(x.get(), issuerKey ? issuerKey : key, EVP_sha256()) <= 0) return {};
    return x;
}

QByteArray keyPem(EVP_PKEY* key)
{
    Bio b(BIO_new(BIO_s_mem()));
    PEM_write_bio_PrivateKey(b.get(), key, nullptr, nullptr, 0, nullptr, nullptr);
    return bioBytes(b.get());
}

QByteArray certPem(X509* cert)
{
    Bio b(BIO_new(BIO_s_mem()));
    PEM_write_bio_X509(b.get(), cert);
    return bioBytes(b.get());
}

/// The document signed as `openssl smime -sign -text` does (detached, multipart/signed), as
/// DDS Security reads governance and permissions documents.
QByteArray smimeSign(const QByteArray& doc, X509* cert, EVP_PKEY* key)
{
    const int flags = PKCS7_DETACHED | PKCS7_TEXT;
    Bio in(BIO_new_mem_buf(doc.constData(), static_cast<int>(doc.size())));
    P7 p7(PKCS7_sign(cert, key, nullptr, in.get(), flags));
    if (!p7) return {};
    Bio data(BIO_new_mem_buf(doc.constData(), static_cast<int>(doc.size())));
    Bio out(BIO_new(BIO_s_mem()));
    if (SMIME_write_PKCS7(out.get(), p7.get(), data.get(), flags) != 1) return {};
    return bioBytes(out.get());
}

/// The PEM file's object, read by `read` (PEM_read_bio_X509, PEM_read_bio_PrivateKey);
/// empty when the file cannot be read or holds none.
template <typename Out, typename Read>
Out readPem(const QString& file, Read read)
{
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly)) return {};
    const QByteArray pem = f.readAll();
    Bio b(BIO_new_mem_buf(pem.constData(), static_cast<int>(pem.size())));
    return Out(read(b.get(), nullptr, nullptr, nullptr));
}

Cert readCert(const QString& file)
{
    return readPem<Cert>(file, PEM_read_bio_X509);
}

Key readKey(const QString& file)
{
    return readPem<Key>(file, PEM_read_bio_PrivateKey);
}

QString domains() { return QStringLiteral("<domains><id_range><min>0</min><max>230</max></id_range></domains>"); }

QByteArray governance()
{
    // every topic of every domain: only authenticated nodes with permissions join; discovery,
    // liveliness, metadata and data encrypted, every RTPS message signed
    return QStringLiteral(
               "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<dds xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
               "xsi:noNamespaceSchemaLocation=\"http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd\">\n"
               "  <domain_access_rules>\n"
               "    <domain_rule>\n"
               "      %1\n"
               "      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>\n"
               "      <enable_join_access_control>true</enable_join_access_control>\n"
               "      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>\n"
               "      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>\n"
               "      <rtps_protection_kind>SIGN</rtps_protection_kind>\n"
               "      <topic_access_rules>\n"
               "        <topic_rule>\n"
               "          <topic_expression>*</topic_expression>\n"
               "          <enable_discovery_protection>true</enable_discovery_protection>\n"
               "          <enable_liveliness_protection>true</enable_liveliness_protection>\n"
               "          <enable_read_access_control>true</enable_read_access_control>\n"
               "          <enable_write_access_control>true</enable_write_access_control>\n"
               "          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>\n"
               "          <data_protection_kind>ENCRYPT</data_protection_kind>\n"
               "        </topic_rule>\n"
               "      </topic_access_rules>\n"
               "    </domain_rule>\n"
               "  </domain_access_rules>\n"
               "</dds>\n")
        .arg(domains())
        .toUtf8();
}

QByteArray permissions(const QString& name)
{
    const QDateTime now = QDateTime::currentDateTimeUtc();
    const QString format = QStringLiteral("yyyy-MM-ddTHH:mm:ss");
    const QString n = name.toHtmlEscaped();
    return QStringLiteral(
               "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<dds xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
               "xsi:noNamespaceSchemaLocation=\"http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd\">\n"
               "  <permissions>\n"
               "    <grant name=\"%1\">\n"
               "      <subject_name>CN=%1</subject_name>\n"
               "      <validity><not_before>%2</not_before><not_after>%3</not_after></validity>\n"
               "      <allow_rule>\n"
               "        %4\n"
               "        <publish><topics><topic>padrob_*</topic></topics></publish>\n"
               "        <subscribe><topics><topic>padrob_*</topic></topics></subscribe>\n"
               "      </allow_rule>\n"
               "      <default>DENY</default>\n"
               "    </grant>\n"
               "  </permissions>\n"
               "</dds>\n")
        .arg(n, now.addDays(-1).toString(format), now.addYears(kYears).toString(format), domains())
        .toUtf8();
}

QString opensslFailed(const QString& what) { return QCoreApplication::translate("CentrePki", "OpenSSL could not make %1.").arg(what); }

}  // namespace

NodeFiles nodeFiles(const QString& dir, const QString& node)
{
    const QString nd = QDir(dir).filePath(QStringLiteral("nodes/") + node);
    return {path(dir, "identity_ca.pem"), path(dir, "permissions_ca.pem"), path(dir, "governance.p7s"),
            path(nd, "identity.pem"),     path(nd, "identity.key"),         path(nd, "permissions.p7s")};
}

bool validNodeName(const QString& name)
{
    static const QRegularExpression re(QStringLiteral("^[A-Za-z0-9][A-Za-z0-9._@-]{0,63}$"));
    return re.match(name).hasMatch();
}

bool createCentre(const QString& dir, QString* error)
{
    if (QFileInfo::exists(path(dir, "identity_ca.pem")) || QFileInfo::exists(path(dir, "permissions_ca.pem"))) {
        if (error) *error = QCoreApplication::translate("CentrePki", "%1 holds a centre's PKI already: it is never replaced.").arg(dir);
        return false;
    }
    if (!QDir().mkpath(dir)) {
        if (error) *error = QCoreApplication::translate("CentrePki", "Could not make the folder %1.").arg(dir);
        return false;
    }
    Key idKey = newKey(), permKey = newKey();
    if (!idKey || !permKey) {
        if (error) *error = opensslFailed(QCoreApplication::translate("CentrePki", "the CAs' keys"));
        return false;
    }
    Cert idCa = makeCert(idKey.get(), QStringLiteral("Padrob centre identity CA"), true, nullptr, nullptr);
    Cert permCa = makeCert(permKey.get(), QStringLiteral("Padrob centre permissions CA"), true, nullptr, nullptr);
    if (!idCa || !permCa) {
        if (error) *error = opensslFailed(QCoreApplication::translate("CentrePki", "the CAs' certificates"));
        return false;
    }
    const QByteArray gov = governance();
    const QByteArray govSigned = smimeSign(gov, permCa.get(), permKey.get());
    if (govSigned.isEmpty()) {
        if (error) *error = opensslFailed(QCoreApplication::translate("CentrePki", "the signed governance document"));
        return false;
    }
    return writeNew(path(dir, "identity_ca.key"), keyPem(idKey.get()), true, error) &&
           writeNew(path(dir, "identity_ca.pem"), certPem(idCa.get()), false, error) &&
           writeNew(path(dir, "permissions_ca.key"), keyPem(permKey.get()), true, error) &&
           writeNew(path(dir, "permissions_ca.pem"), certPem(permCa.get()), false, error) &&
           writeNew(path(dir, "governance.xml"), gov, false, error) &&
           writeNew(path(dir, "governance.p7s"), govSigned, false, error);
}

bool issueNode(const QString& dir, const QString& name, QString* error)
{
    if (!validNodeName(name)) {
        if (error) *error = QCoreApplication::translate("CentrePki", "'%1' cannot be a node's name in the centre's PKI: use letters, digits and - _ . @ (up to 64).").arg(name);
        return false;
    }
    Cert idCa = readCert(path(dir, "identity_ca.pem")), permCa = readCert(path(dir, "permissions_ca.pem"));
    Key idKey = readKey(path(dir, "identity_ca.key")), permKey = readKey(path(dir, "permissions_ca.key"));
    if (!idCa || !permCa || !idKey || !permKey) {
        if (error)
            *error = QCoreApplication::translate("CentrePki", "%1 has no centre PKI (identity_ca.pem/.key, permissions_ca.pem/.key): make it with 'padrob centre pki %1'.").arg(dir);
        return false;
    }
    const NodeFiles files = nodeFiles(dir, name);
    const QString nodeDir = QFileInfo(files.certificate).absolutePath();
    if (QFileInfo::exists(files.certificate)) {
        if (error) *error = QCoreApplication::translate("CentrePki", "Node %1 has an identity already in %2: it is never replaced.").arg(name, nodeDir);
        return false;
    }
    if (!QDir().mkpath(nodeDir)) {
        if (error) *error = QCoreApplication::translate("CentrePki", "Could not make the folder %1.").arg(nodeDir);
        return false;
    }
    Key key = newKey();
    Cert cert = key ? makeCert(key.get(), name, false, idCa.get(), idKey.get()) : Cert();
    if (!cert) {
        if (error) *error = opensslFailed(QCoreApplication::translate("CentrePki", "the node's certificate"));
        return false;
    }
    const QByteArray perms = permissions(name);
    const QByteArray permsSigned = smimeSign(perms, permCa.get(), permKey.get());
    if (permsSigned.isEmpty()) {
        if (error) *error = opensslFailed(QCoreApplication::translate("CentrePki", "the signed permissions document"));
        return false;
    }
    return writeNew(files.privateKey, keyPem(key.get()), true, error) &&
           writeNew(files.certificate, certPem(cert.get()), false, error) &&
           writeNew(QDir(nodeDir).filePath(QStringLiteral("permissions.xml")), perms, false, error) &&
           writeNew(files.permissions, permsSigned, false, error);
}

bool checkNode(const QString& dir, const QString& name, QString* error)
{
    auto fail = [&](const QString& why) {
        if (error) *error = why;
        return false;
    };
    const NodeFiles f = nodeFiles(dir, name);
    for (const QString& file : f.all()) {
        if (!QFileInfo(file).isFile()) {
            return fail(QCoreApplication::translate("CentrePki", "DDS Security: %1 is missing. Issue this node's identity with 'padrob centre pki %2 --node %3' "
                           "on the computer that holds the centre's PKI, and copy the files here.")
                            .arg(file, dir, name));
        }
    }
    Cert ca = readCert(f.identityCa), cert = readCert(f.certificate);
    if (!ca) return fail(QCoreApplication::translate("CentrePki", "DDS Security: %1 is not a certificate. Copy the centre's identity_ca.pem again.").arg(f.identityCa));
    if (!cert) {
        return fail(QCoreApplication::translate("CentrePki", "DDS Security: %1 is not a certificate. Issue this node's identity again with 'padrob centre pki %2 --node %3'.")
                        .arg(f.certificate, dir, name));
    }
    if (X509_verify(cert.get(), X509_get0_pubkey(ca.get())) != 1) {
        return fail(QCoreApplication::translate("CentrePki", "DDS Security: %1 was not issued by this centre's identity CA (%2). Issue this node's identity with "
                       "'padrob centre pki DIR --node %3' using the centre's PKI.")
                        .arg(f.certificate, f.identityCa, name));
    }
    if (X509_cmp_current_time(X509_get0_notBefore(cert.get())) >= 0 || X509_cmp_current_time(X509_get0_notAfter(cert.get())) <= 0) {
        return fail(QCoreApplication::translate("CentrePki", "DDS Security: %1 is not valid now (expired, or this computer's clock is wrong). Check the clock, or "
                       "issue a new identity for the node.")
                        .arg(f.certificate));
    }
    Key key = readKey(f.privateKey);
    if (!key || X509_check_private_key(cert.get(), key.get()) != 1) {
        return fail(QCoreApplication::translate("CentrePki", "DDS Security: %1 is not the private key of %2. Copy the node's folder again.").arg(f.privateKey, f.certificate));
    }
    return true;
}

}  // namespace trainer::centre::pki
